#!/usr/bin/env python3
"""Helper of scripts/compare_pysph.sh: parse PySPH's cube runs and ours, write the comparison.

Two sub-commands:

  neighbours NPZ...   (run with the PySPH venv's python) mean neighbours per particle of PySPH
                      output files, found with PySPH's own LinkedListNNPS at the example's
                      kernel support (CubicSpline: radius_scale 2, i.e. 2h = 3 dx). Prints JSON.
  summarise ...       (stdlib only) reads the run folders, prints the table and writes the
                      markdown fragment.

What is counted for PySPH (pysph.examples.cube, PySPH 1.0b2):
  * particles: the array size logged as "fluid: N" (21,952 for --np 20000: numpy.mgrid with
    dx = 1/20000^(1/3) gives 28 points per axis);
  * steps: the call count of Integrator.stage2 in the run's profile_info.csv (one per time
    step of the PEC integrator), checked against acceleration_eval_0;
  * wall time: cpu_time in the run's cube.info, the wall time of Application.solve() that
    PySPH prints as "Run took" (it does not include "Setup took": argument parsing, particle
    creation and the Cython compilation). It includes the one initial acceleration evaluation
    that the PEC integrator does before the time loop; that share is reported.
  particle-steps/s = particles × steps / wall time.
"""

import argparse
import csv
import json
import math
import os
import re
import statistics
import sys


# --------------------------------------------------------------------------------------------
# neighbours (PySPH side; needs the venv)


def cmd_neighbours(args):
    import numpy as np
    from cyarray.carray import UIntArray
    from pysph.base.kernels import CubicSpline
    from pysph.base.nnps import LinkedListNNPS
    from pysph.solver.utils import load

    radius_scale = CubicSpline(dim=3).radius_scale  # the example's kernel
    out = []
    for fname in args.npz:
        data = load(fname)
        pa = data["arrays"]["fluid"]
        n = pa.get_number_of_particles()
        nnps = LinkedListNNPS(dim=3, particles=[pa], radius_scale=radius_scale)
        nnps.set_context(0, 0)
        nbrs = UIntArray()
        counts = np.empty(n, dtype=np.int64)
        for i in range(n):
            nnps.get_nearest_particles(0, 0, i, nbrs)
            counts[i] = nbrs.length
        # PySPH's lists hold the particle itself; ours do not: report both.
        out.append(
            {
                "file": os.path.basename(fname),
                "t": float(data["solver_data"]["t"]),
                "count": int(data["solver_data"]["count"]),
                "particles": int(n),
                "h": float(pa.h[0]),
                "radius_scale": float(radius_scale),
                "mean_with_self": float(counts.mean()),
                "mean_excluding_self": float(counts.mean() - 1.0),
            }
        )
    json.dump(out, sys.stdout, indent=1)
    print()


# --------------------------------------------------------------------------------------------
# summarise (stdlib only)


def lattice_neighbours(n, r_over_dx, inclusive=False):
    """Mean number of other points within r (< r, or <= r) of a point of an n³ cubic lattice."""
    reach = int(math.ceil(r_over_dx))
    r2 = r_over_dx * r_over_dx * (1.0 + (1e-12 if inclusive else -1e-12))
    total = 0
    for i in range(-reach, reach + 1):
        for j in range(-reach, reach + 1):
            for k in range(-reach, reach + 1):
                d2 = i * i + j * j + k * k
                if 0 < d2 < r2:
                    total += max(n - abs(i), 0) * max(n - abs(j), 0) * max(n - abs(k), 0)
    return total / n**3


def pysph_run(folder):
    with open(os.path.join(folder, "cube.info")) as f:
        info = json.load(f)
    if not info.get("completed"):
        raise SystemExit(f"{folder}: PySPH run did not complete")
    prof = {}
    with open(os.path.join(folder, "profile_info.csv")) as f:
        for row in csv.DictReader(f):
            prof[row["function"]] = (int(row["calls"]), float(row["time"]))
    steps = prof["Integrator.stage2"][0]
    if prof.get("acceleration_eval_0", (steps,))[0] != steps:
        raise SystemExit(f"{folder}: stage2 and acceleration_eval_0 counts differ")
    with open(os.path.join(folder, "stdout.log")) as f:
        log = f.read()
    m = re.search(r"fluid:\s*(\d+)", log)
    if not m:
        raise SystemExit(f"{folder}: no particle count in stdout.log")
    particles = int(m.group(1))
    m = re.search(r"Run took:\s*([0-9.eE+-]+)", log)
    wall = float(info["cpu_time"])  # == "Run took"
    if m and abs(float(m.group(1)) - wall) > 1e-3:
        raise SystemExit(f"{folder}: cube.info and 'Run took' disagree")
    setup = re.search(r"Setup took:\s*([0-9.eE+-]+)", log)
    init_acc = prof.get("Integrator.initial_acceleration", (0, 0.0))[1]
    return {
        "particles": particles,
        "steps": steps,
        "wall_s": wall,
        "setup_s": float(setup.group(1)) if setup else float("nan"),
        "initial_acceleration_s": init_acc,
        "pss": particles * steps / wall,
    }


def ours_run(folder):
    with open(os.path.join(folder, "run_info.json")) as f:
        info = json.load(f)
    if info.get("status") != "completed":
        raise SystemExit(f"{folder}: run status {info.get('status')}")
    return {
        "particles": info["fluid_particles"],
        "steps": info["steps"],
        "wall_s": info["wall_time_s"],
        "pss": info["particle_steps_per_second"],
        "mean_neighbours": info["mean_neighbours"],
        "simulated_time_s": info["simulated_time_s"],
        "git_revision": info.get("git_revision", "?"),
        "scene_file": info.get("scene_file", "?"),
        "effects": info.get("effects", []),
        "scene": info.get("scene", {}),
    }


def fmt(x, digits=3):
    return f"{x:.{digits}g}" if isinstance(x, float) else str(x)


def cmd_summarise(a):
    py = [pysph_run(d) for d in a.pysph_runs]
    us = [ours_run(d) for d in a.ours_runs]
    with open(a.pysph_neighbours) as f:
        nb = json.load(f)
    machine = json.loads(a.machine)

    py_pss = statistics.median(r["pss"] for r in py)
    us_pss = statistics.median(r["pss"] for r in us)
    # PySPH: mean neighbours (excluding self, like ours) at the end of the warm-up run, which
    # runs the same steps as the timed runs; the initial lattice value is given too.
    py_nb_end = nb[-1]["mean_excluding_self"]
    py_nb_start = nb[0]["mean_excluding_self"]
    us_nb = statistics.median(r["mean_neighbours"] for r in us)
    py_pair = py_pss * py_nb_end
    us_pair = us_pss * us_nb
    ratio_pss = us_pss / py_pss
    ratio_pair = us_pair / py_pair

    d = us[0]["scene"].get("discretisation", {})
    n_side = round(us[0]["particles"] ** (1 / 3))
    re_l0 = d.get("re_over_l0", float("nan"))
    skin = d.get("neighbour_skin_over_l0", 0.0)
    support_l0 = 2.0 * d.get("h_over_l0", float("nan"))  # Wendland C2: support 2h
    list_l0 = max(re_l0, support_l0) + skin
    us_lat_list = lattice_neighbours(n_side, list_l0)
    us_lat_re = lattice_neighbours(n_side, max(re_l0, support_l0))
    py_side = round(py[0]["particles"] ** (1 / 3))
    py_r = nb[0]["radius_scale"] * 1.5  # 2h = 2 × 1.5 dx
    py_lat = (lattice_neighbours(py_side, py_r), lattice_neighbours(py_side, py_r, True))

    def verdict(r, target):
        return "meets" if r >= target else "misses"

    # the targets: at the default setting (r_e = 4.2 l0) 3× the particle-steps/s and 10× the
    # pair rate; at r_e = 2.1 l0 5× the particle-steps/s (no pair-rate target)
    steps_target, pairs_target = (3.0, 10.0) if re_l0 >= 4.0 else (5.0, None)

    def target(r, t):
        return "–" if t is None else f"≥ {t:g}× ({verdict(r, t)})"

    lines = []
    lines.append("## Speed against PySPH's 3D WCSPH cube example")
    lines.append("")
    lines.append(
        f"Measured {machine['date']} with `scripts/compare_pysph.sh` (REPS={len(py)}, "
        f"{machine['threads']} threads each, back to back: {machine['order']})."
    )
    lines.append("")
    scene_file = us[0]["scene_file"]
    scene_name = os.path.splitext(os.path.basename(scene_file))[0]
    lines.append(f"| | PySPH cube | ours: {scene_name} | ours / PySPH | target |")
    lines.append("| --- | --- | --- | --- | --- |")
    lines.append(f"| runs | {len(py)} | {len(us)} | | |")
    lines.append(
        f"| fluid particles | {py[0]['particles']:,} | {us[0]['particles']:,} | | |"
    )
    lines.append(f"| steps per run | {py[0]['steps']} | {us[0]['steps']} | | |")
    lines.append(
        f"| wall time per run, median [s] | {statistics.median(r['wall_s'] for r in py):.2f} "
        f"| {statistics.median(r['wall_s'] for r in us):.2f} | | |"
    )
    lines.append(
        f"| particle-steps/s, median | {py_pss:.4g} | {us_pss:.4g} | **{ratio_pss:.2f}×** "
        f"| {target(ratio_pss, steps_target)} |"
    )
    lines.append(
        f"| mean neighbours per particle | {py_nb_end:.1f} | {us_nb:.1f} | | |"
    )
    lines.append(
        f"| neighbour-pair rate [pairs/s] | {py_pair:.4g} | {us_pair:.4g} | **{ratio_pair:.2f}×** "
        f"| {target(ratio_pair, pairs_target)} |"
    )
    lines.append("")
    lines.append(
        "Particle-steps/s of every run — PySPH: "
        + ", ".join(f"{r['pss']:.4g}" for r in py)
        + "; ours: "
        + ", ".join(f"{r['pss']:.4g}" for r in us)
        + "."
    )
    lines.append("")
    lines.append("How the numbers are obtained:")
    lines.append("")
    lines.append(
        f"- PySPH: `OMP_NUM_THREADS={machine['threads']} python -m pysph.examples.cube --np 20000 "
        f"--openmp --disable-output --tf {machine['pysph_tf']} --max-steps {machine['pysph_steps']}` "
        "(dt = 1e-4 fixed), after one untimed warm-up run that compiles the generated Cython "
        "code. Steps: calls of `Integrator.stage2` in `profile_info.csv`; wall time: `cube.info` "
        "`cpu_time` = the \"Run took\" of `Application.solve()` (excludes \"Setup took\": "
        "parsing, particle creation, compilation; includes the single initial acceleration "
        f"evaluation, {100 * statistics.median(r['initial_acceleration_s'] / r['wall_s'] for r in py):.2f} % of it)."
    )
    lines.append(
        f"- PySPH neighbours: PySPH's `LinkedListNNPS` at the example's kernel support "
        f"(CubicSpline, 2h = 3 dx, h = {nb[0]['h']:.4g}) over the warm-up run's particle arrays, "
        f"the particle itself not counted: {py_nb_start:.1f} at t = 0, {py_nb_end:.1f} at the end "
        f"(t = {nb[-1]['t']:.3g}, used above). Geometric check on the {py_side}³ lattice: "
        f"{py_lat[0]:.1f} closer than 3 dx, {py_lat[1]:.1f} within 3 dx inclusive; the lattice "
        "pairs at exactly 3 dx (zero kernel weight) fall either side by round-off. PySPH loops "
        "over all of these and the particle itself."
    )
    lines.append(
        f"- Ours: `verify run {scene_file} --threads {machine['threads']}`, "
        "`run_info.json`: `particle_steps_per_second` (fluid particles × steps / wall time of "
        "the time loop, set-up excluded) and `mean_neighbours` (neighbours closer than "
        f"max(2h, r_e) = {max(re_l0, support_l0):.2f} l0 at the end, self excluded). A bulk "
        f"particle of the initial {n_side}³ lattice has {us_lat_re:.1f} there, a disordered "
        f"liquid of the same density (4/3)π({max(re_l0, support_l0):.2f})³ = "
        f"{4.0 / 3.0 * math.pi * max(re_l0, support_l0) ** 3:.1f}; surface particles have fewer. The "
        f"Verlet lists also hold the skin's shell (radius {list_l0:.2f} l0, {us_lat_list:.1f} on "
        "the lattice), which the density sum visits (it marks the entries that interact) and "
        "the force loop skips; the shell is not counted."
    )
    lines.append(f"- Our effects: {', '.join(us[0]['effects'])}.")
    lines.append(f"- Our revision: {us[0]['git_revision']}.")
    lines.append("")
    lines.append("Machine:")
    lines.append("")
    lines.append(f"- CPU: {machine['cpu']} ({machine['cores']} cores)")
    lines.append(f"- {machine['rustc']}; {machine['cc']}")
    lines.append(f"- PySPH {machine['pysph']} (Python {machine['python']}, {machine['pydeps']})")
    lines.append(
        f"- load average before: {machine['load_before']}; after: {machine['load_after']}"
    )
    if machine.get("warning"):
        lines.append("")
        lines.append(f"**Warning:** {machine['warning']}")
    text = "\n".join(lines) + "\n"
    os.makedirs(os.path.dirname(os.path.abspath(a.out)), exist_ok=True)
    with open(a.out, "w") as f:
        f.write(text)
    print(text)


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    sub = p.add_subparsers(dest="cmd", required=True)
    n = sub.add_parser("neighbours")
    n.add_argument("npz", nargs="+")
    s = sub.add_parser("summarise")
    s.add_argument("--pysph-runs", nargs="+", required=True)
    s.add_argument("--ours-runs", nargs="+", required=True)
    s.add_argument("--pysph-neighbours", required=True, help="JSON from `neighbours`")
    s.add_argument("--machine", required=True, help="JSON object describing the machine")
    s.add_argument("--out", required=True, help="markdown fragment to write")
    a = p.parse_args()
    if a.cmd == "neighbours":
        cmd_neighbours(a)
    else:
        cmd_summarise(a)


if __name__ == "__main__":
    main()
