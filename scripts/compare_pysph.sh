#!/usr/bin/env bash
# Speed comparison with PySPH's own 3D WCSPH cube example (`pysph.examples.cube --np 20000
# --openmp`). Targets: at the default setting (r_e = 4.2 l0) at least 3× its particle-steps per
# second and 10× its neighbour-pair rate (particle-steps/s × mean neighbours per particle); at
# r_e = 2.1 l0 at least 5× its particle-steps per second. Medians of
# REPS runs each, measured in the same session back to back on THREADS threads.
#
# Usage: scripts/compare_pysph.sh [OUT.md]        (default reports/performance_pysph.md)
#
# Environment (all optional):
#   REPS=5               timed runs of each code
#   THREADS=2            OpenMP threads for PySPH (OMP_NUM_THREADS), --threads for ours
#   PYSPH_STEPS=200      PySPH time steps per run (dt = 1e-4 fixed by the example)
#   SCENE=scenes/bench_cube_20k.toml   our scene (~19.7 k particles, ~2000 steps)
#   ORDER=blocked        blocked: all PySPH runs, then all of ours; interleaved: alternate
#   PYTHON=python3.11    interpreter for the venv (needs its headers: Python.h)
#   PYSPH_VENV=DIR       reuse an existing venv with PySPH instead of making a throw-away one
#   KEEP_WORK=1          keep the work folder (venv, logs, run folders) for inspection
#
# Needs: a C compiler with OpenMP (cc -fopenmp), PyPI access, cargo. The first install builds
# PySPH from its source distribution (a few minutes on 2 cores; pip caches the wheel after that).
# Each PySPH run compiles nothing: the generated Cython code is compiled by an untimed warm-up
# run into a throw-away HOME, which also supplies PySPH's neighbour count.
set -euo pipefail

OUT_MD="$(realpath -m "${1:-reports/performance_pysph.md}")"
cd "$(dirname "$0")/.."
ROOT="$PWD"

REPS="${REPS:-5}"
THREADS="${THREADS:-2}"
PYSPH_STEPS="${PYSPH_STEPS:-200}"
SCENE="${SCENE:-scenes/bench_cube_20k.toml}"
ORDER="${ORDER:-blocked}"
PYTHON="${PYTHON:-python3.11}"
KEEP_WORK="${KEEP_WORK:-0}"

# Pinned PySPH and the packages it compiles the example with at run time.
PYSPH_VERSION="1.0b2"
PYSPH_PINS=(
  "pysph==${PYSPH_VERSION}" "Cython==3.3.1" "numpy==2.4.6" "compyle==0.9.1" "cyarray==1.2"
  "mako==1.4.3" "Beaker==1.14.1" "pytools==2026.1.1"
)
PYSPH_NP=20000
PYSPH_DT=1e-4 # the example's fixed time step
PYSPH_TF="$("$PYTHON" -c "print(round(${PYSPH_STEPS} * ${PYSPH_DT}, 12))")"

log() { printf '[compare_pysph] %s\n' "$*" >&2; }
die() { log "error: $*"; exit 1; }

case "$ORDER" in blocked | interleaved) ;; *) die "ORDER must be blocked or interleaved" ;; esac
[[ "$REPS" =~ ^[1-9][0-9]*$ ]] || die "REPS must be a positive integer"
[[ -f "$SCENE" ]] || die "no scene $SCENE"

WORK="$(mktemp -d "${TMPDIR:-/tmp}/compare_pysph.XXXXXX")"
if [[ "$KEEP_WORK" == 1 ]]; then
  log "work folder (kept): $WORK"
else
  trap 'rm -rf "$WORK"' EXIT
fi

# --- prerequisites ------------------------------------------------------------------------
echo 'int main(void){return 0;}' > "$WORK/omp.c"
"${CC:-cc}" -fopenmp "$WORK/omp.c" -o "$WORK/omp" 2>/dev/null ||
  die "${CC:-cc} cannot compile with -fopenmp (PySPH's --openmp needs it)"
"$PYTHON" -c 'import sysconfig, os, sys; sys.exit(not os.path.exists(os.path.join(sysconfig.get_paths()["include"], "Python.h")))' ||
  die "$PYTHON has no Python.h (install its -dev package)"

# --- PySPH in a throw-away venv -----------------------------------------------------------
if [[ -n "${PYSPH_VENV:-}" ]]; then
  VENV="$PYSPH_VENV"
  log "using the venv $VENV"
else
  VENV="$WORK/venv"
  log "installing PySPH ${PYSPH_VERSION} into $VENV (log: pip.log in the work folder)"
  "$PYTHON" -m venv "$VENV"
  if ! { "$VENV/bin/python" -m pip install --upgrade pip &&
    "$VENV/bin/python" -m pip install "${PYSPH_PINS[@]}"; } > "$WORK/pip.log" 2>&1; then
    tail -30 "$WORK/pip.log" >&2
    die "pip install failed"
  fi
fi
VPY="$VENV/bin/python"
PYSPH_REPORTED="$("$VPY" -c 'import pysph; print(pysph.__version__)')"
PYDEPS="$("$VPY" -m pip freeze 2>/dev/null | grep -iE '^(cython|numpy|compyle|cyarray)==' | paste -sd ' ' -)"

# PySPH compiles the example into ~/.pysph: give it a HOME of its own so that the warm-up run
# really compiles and nothing outside the work folder is touched.
PYSPH_HOME="$WORK/home"
mkdir -p "$PYSPH_HOME" "$WORK/pysph" "$WORK/ours"

run_pysph() { # folder, extra options...
  local dir="$1"
  shift
  mkdir -p "$dir"
  (cd "$WORK" && env HOME="$PYSPH_HOME" OMP_NUM_THREADS="$THREADS" \
    "$VPY" -m pysph.examples.cube --np "$PYSPH_NP" --openmp -d "$dir" \
    --tf "$PYSPH_TF" --max-steps "$PYSPH_STEPS" "$@") > "$dir/stdout.log" 2>&1 ||
    { tail -20 "$dir/stdout.log" >&2; die "PySPH run in $dir failed"; }
}

run_ours() { # folder
  local dir="$1"
  cargo run --release -q -p verify -- run "$SCENE" --out "$dir" --threads "$THREADS" --force \
    > "$dir.log" 2>&1 || { tail -20 "$dir.log" >&2; die "our run in $dir failed"; }
}

# --- warm-up (untimed) ----------------------------------------------------------------------
log "PySPH warm-up: compiles the example; writes the first and last states for the neighbour count"
run_pysph "$WORK/pysph/warmup" --pfreq 100000000
grep -h "Setup took\|Run took" "$WORK/pysph/warmup/stdout.log" | sed 's/^/  warm-up: /' >&2
mapfile -t NPZ < <(ls "$WORK"/pysph/warmup/cube_*.npz | sort)
[[ ${#NPZ[@]} -ge 2 ]] || die "the warm-up run wrote no output files"
"$VPY" "$ROOT/scripts/compare_pysph.py" neighbours "${NPZ[0]}" "${NPZ[-1]}" > "$WORK/pysph_neighbours.json"

log "building our solver (untimed)"
cargo build --release -q -p verify

# --- timed runs, back to back -------------------------------------------------------------
# Other work: the load average still holds the warm-up and the build just done, so it is only
# recorded; the check counts runnable processes besides this script, sampled 10 times over 2 s.
LOAD_BEFORE="$(cut -d' ' -f1-3 /proc/loadavg)"
BUSY=0
for _ in $(seq 10); do
  read -r _ _ _ rt _ < /proc/loadavg   # "runnable/total"; a builtin: only this shell runs
  [[ "${rt%%/*}" -gt 1 ]] && BUSY=$((BUSY + 1))
  sleep 0.2
done
PY_DIRS=()
OUR_DIRS=()
one_pysph() {
  local d="$WORK/pysph/run_$1"
  run_pysph "$d" --disable-output
  PY_DIRS+=("$d")
  log "PySPH run $1/$REPS: $(grep -h 'Run took' "$d/stdout.log")"
}
one_ours() {
  local d="$WORK/ours/run_$1"
  run_ours "$d"
  OUR_DIRS+=("$d")
  log "our run $1/$REPS: $(tail -1 "$d.log")"
}
if [[ "$ORDER" == blocked ]]; then
  for k in $(seq "$REPS"); do one_pysph "$k"; done
  for k in $(seq "$REPS"); do one_ours "$k"; done
else
  for k in $(seq "$REPS"); do
    one_pysph "$k"
    one_ours "$k"
  done
fi
LOAD_AFTER="$(cut -d' ' -f1-3 /proc/loadavg)"

# --- machine and summary ------------------------------------------------------------------
WARNING=""
if [[ "$BUSY" -ge 3 ]]; then
  WARNING="other processes were runnable in $BUSY of 10 samples just before the timed runs: other work was running, the numbers are not representative."
fi
[[ "$REPS" -lt 5 ]] && WARNING="${WARNING:+$WARNING }only $REPS run(s) each: the target asks for the median of at least 5."

export M_DATE="$(date -u '+%Y-%m-%d %H:%M UTC')"
export M_CPU="$(lscpu | sed -n 's/^Model name:[[:space:]]*//p' | head -1)"
# the vector extensions the numbers depend on (present or not)
FLAGS="$(grep -m1 '^flags' /proc/cpuinfo || true)"
VEC=""
for f in avx2 fma avx512f; do
  if [[ " $FLAGS " == *" $f "* ]]; then VEC="${VEC:+$VEC, }$f"; else VEC="${VEC:+$VEC, }no $f"; fi
done
export M_CPU="$M_CPU; $VEC"

export M_CORES="$(nproc)"
export M_RUSTC="$(rustc --version)"
export M_CC="$("${CC:-cc}" --version | head -1)"
export M_PYSPH="$PYSPH_REPORTED" M_PYDEPS="$PYDEPS"
export M_PYTHON="$("$VPY" -c 'import platform; print(platform.python_version())')"
export M_THREADS="$THREADS" M_ORDER="$ORDER" M_STEPS="$PYSPH_STEPS" M_TF="$PYSPH_TF"
export M_LOAD_BEFORE="$LOAD_BEFORE" M_LOAD_AFTER="$LOAD_AFTER" M_WARNING="$WARNING"
MACHINE="$("$PYTHON" -c '
import json, os
keys = ["date", "cpu", "cores", "rustc", "cc", "pysph", "pydeps", "python", "threads", "order",
        "load_before", "load_after", "warning"]
m = {k: os.environ["M_" + k.upper()] for k in keys}
m["pysph_steps"], m["pysph_tf"] = os.environ["M_STEPS"], os.environ["M_TF"]
print(json.dumps(m))')"

"$PYTHON" "$ROOT/scripts/compare_pysph.py" summarise \
  --pysph-runs "${PY_DIRS[@]}" --ours-runs "${OUR_DIRS[@]}" \
  --pysph-neighbours "$WORK/pysph_neighbours.json" --machine "$MACHINE" --out "$OUT_MD"
log "written: $OUT_MD"
