#!/usr/bin/env python3
"""A run's outputs in Python: a drop's height against time, from the time series and from the
particle snapshots, plotted to a PNG.

    python3 scripts/drop_height.py RUN_DIR [--liquid NAME] [--png FILE]

RUN_DIR is the folder of `verify run SCENE --out RUN_DIR --vtk N`. It reads
- `run_info.json` (the resolved scene: the liquids, the spacing l0),
- `timeseries.csv` with pandas (`<liquid>_extent_z_m`: the liquid's extent along z, from the
  lowest to the highest particle centre),
- `particles.pvd` and its `.vtu` snapshots with meshio (the particles of each snapshot),
checks that the two agree at every snapshot (they are the same particles), and plots the height
`extent_z + l0` (a particle stands for a cube of side l0) in mm against time in ms.

Needs pandas, meshio and matplotlib (`pip install pandas meshio matplotlib`).
"""

import argparse
import json
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import meshio  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402


def snapshots(run: Path):
    """(time [s], points [m], phase) of each fluid snapshot listed in particles.pvd."""
    pvd = ET.parse(run / "particles.pvd").getroot()
    for ds in pvd.iter("DataSet"):
        if ds.get("part") != "0":
            continue  # part 1: the walls
        mesh = meshio.read(run / ds.get("file"))
        yield float(ds.get("timestep")), mesh.points, mesh.point_data["phase"]


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("run", type=Path)
    ap.add_argument("--liquid", help="the liquid (default: the scene's first)")
    ap.add_argument("--png", type=Path, help="output (default: RUN/drop_height.png)")
    a = ap.parse_args()

    info = json.loads((a.run / "run_info.json").read_text())
    liquids = [l["name"] for l in info["scene"]["liquid"]]
    liquid = a.liquid or liquids[0]
    if liquid not in liquids:
        print(f"error: no liquid {liquid!r} in the scene (it has {liquids})", file=sys.stderr)
        return 2
    phase = liquids.index(liquid)
    l0 = info["scene"]["discretisation"]["l0"]

    ts = pd.read_csv(a.run / "timeseries.csv")
    height_mm = (ts[f"{liquid}_extent_z_m"] + l0) * 1e3

    snap_t, snap_h = [], []
    for t, pts, ph in snapshots(a.run):
        z = pts[np.asarray(ph) == phase, 2]
        h = (z.max() - z.min() + l0) * 1e3
        row = ts.iloc[(ts["time_s"] - t).abs().argmin()]
        if abs(row["time_s"] - t) > 1e-9 * max(1.0, t) + 1e-12:
            print(f"error: snapshot at t = {t} s has no time-series row", file=sys.stderr)
            return 1
        expected = (row[f"{liquid}_extent_z_m"] + l0) * 1e3
        if abs(h - expected) > 1e-9 * expected:
            print(f"error: at t = {t} s the snapshot's height {h} mm differs from the time series' {expected} mm", file=sys.stderr)
            return 1
        snap_t.append(t * 1e3)
        snap_h.append(h)
    if not snap_t:
        print("error: no snapshots (run with --vtk N)", file=sys.stderr)
        return 1

    png = a.png or a.run / "drop_height.png"
    fig, ax = plt.subplots(figsize=(6, 4))
    ax.plot(ts["time_s"] * 1e3, height_mm, label="time series")
    ax.plot(snap_t, snap_h, "o", label="snapshots (.vtu)")
    ax.set_xlabel("t [ms]")
    ax.set_ylabel(f"height of the {liquid} [mm]")
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(f"{len(snap_t)} snapshots agree with the time series; height {height_mm.iloc[0]:.4f} → {height_mm.iloc[-1]:.4f} mm; plot: {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
