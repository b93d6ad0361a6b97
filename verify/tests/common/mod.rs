//! What several test files share: the `verify` binary, a small scene, and a quiet way to run a
//! command. (Each test file uses some of them.)
#![allow(dead_code)]

use std::process::{Command, ExitStatus};

/// Runs a command with its output captured instead of inherited, so the test log stays quiet;
/// when the command fails, its stderr goes to the test's own (captured) output, which the
/// harness shows with the failure.
pub trait Quiet {
    /// Like `status()`, without printing the command's output.
    fn quiet(&mut self) -> std::io::Result<ExitStatus>;
}

impl Quiet for Command {
    fn quiet(&mut self) -> std::io::Result<ExitStatus> {
        let out = self.output()?;
        if !out.status.success() {
            eprintln!("{}", String::from_utf8_lossy(&out.stderr));
        }
        Ok(out.status)
    }
}

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
