#!/usr/bin/env bash
# Once every task of the plan has finished: collect it with the re-run's binary (which relaxes
# the water–oil–Teflon slabs, a simulation, so they come from the same revision as the runs),
# then with the current binary (the current analysis; it reuses the slabs of the same scene),
# and put the results in reports/ and the baseline. Nothing is committed.
# usage: rerun/finish.sh RERUN_VERIFY CURRENT_VERIFY PLAN
set -euo pipefail
old="$1" new="$2" plan="$3"
repo="$(cd "$(dirname "$0")/.." && pwd)"
left=$(python3 - "$plan" <<'PY'
import json, os, sys
plan = sys.argv[1]
tasks = json.load(open(os.path.join(plan, "plan.json")))["tasks"]
print(sum(1 for t in tasks if not os.path.exists(os.path.join(plan, t["dir"], "particles_final.csv"))))
PY
)
[ "$left" = 0 ] || { echo "$left task(s) not finished" >&2; exit 1; }
"$old" collect "$plan"
"$new" collect "$plan"
for case_dir in "$plan"/*/; do
  name=$(basename "$case_dir")
  case "$name" in scenes|logs) continue ;; esac
  rm -rf "$repo/reports/$name"
  mkdir -p "$repo/reports/$name"
  (cd "$case_dir" && tar --exclude='checkpoint*' --exclude='particles_t*.csv' --exclude='*.vtu' \
      --exclude='walls.csv' -cf - .) | (cd "$repo/reports/$name" && tar -xf -)
done
for f in summary.md summary.csv costs.csv suite.json; do cp "$plan/$f" "$repo/reports/$f"; done
cp "$plan/summary.csv" "$repo/reference/baseline_standard.csv"
echo "reports/ and the baseline now hold the re-run; delete rerun/ when they are committed"
