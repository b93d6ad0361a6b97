#!/usr/bin/env bash
# The Python example end to end: a small drop run with snapshots, then scripts/drop_height.py
# reads its time series, record and VTU series (pandas, meshio) and checks they agree.
# Needs python3 with pandas, meshio and matplotlib (`pip install pandas meshio matplotlib`).
# Run by the nightly workflow.
set -euo pipefail
cd "$(dirname "$0")/.."
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
cat > "$dir/scene.toml" <<'TOML'
description = "a small matte drop relaxing (Python example)"
[discretisation]
l0 = 1.0e-4
sound_speed = 12.5
[time]
end = 4.0e-5
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
shape = { kind = "sphere", center = [0.0, 0.0, 0.0], radius = 8.0e-4 }
TOML
# --strict: the example passes its own pre-flight (8 spacings per radius, c by the cohesion rule)
cargo run --release -q -p verify -- run "$dir/scene.toml" --out "$dir/run" --vtk 2 --strict
python3 scripts/drop_height.py "$dir/run" --png "$dir/drop_height.png"
test -s "$dir/drop_height.png"
