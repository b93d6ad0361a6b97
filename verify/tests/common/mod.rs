//! What several test files share: the `verify` binary and a small scene.

use std::process::Command;

/// The `verify` binary of this build.
pub fn verify() -> Command {
    Command::new(env!("CARGO_BIN_EXE_verify"))
}

/// A small matte drop (R = 4 l0) relaxing in zero gravity for two outputs.
pub const SMALL: &str = r#"
description = "a small matte drop relaxing"
[discretisation]
l0 = 1.0e-4
sound_speed = 12.0
[time]
end = 2.0e-5
output_interval = 1.0e-5
[effects]
interfacial_tension = true
laminar_viscosity = true
[[liquid]]
name = "matte"
density = 4500.0
viscosity = 3.13e-3
surface_tension = 0.4
[[body]]
name = "drop"
liquid = "matte"
shape = { kind = "sphere", center = [0.0, 0.0, 0.0], radius = 4.0e-4 }
"#;
