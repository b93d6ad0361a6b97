#!/usr/bin/env bash
# Carries a plan's task folders between machines that stop (runs longer than one machine's
# life): `save PLAN` copies every finished task folder, and every stopped one with its
# checkpoint, into rerun/tasks/; `load PLAN` copies them back into a plan written by the same
# revision, so `verify task` skips the finished tasks and resumes the stopped ones.
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
stage="$here/tasks"
case "${1:-}" in
save)
  plan="$2"
  python3 - "$plan" "$stage" <<'PY'
import json, os, shutil, sys
plan, stage = sys.argv[1], sys.argv[2]
tasks = json.load(open(os.path.join(plan, "plan.json")))["tasks"]
saved = stopped = 0
for t in tasks:
    src = os.path.join(plan, t["dir"])
    info = os.path.join(src, "run_info.json")
    if not os.path.exists(info):
        continue
    status = json.load(open(info)).get("status")
    done = status in ("completed", "failed") and os.path.exists(os.path.join(src, "particles_final.csv"))
    has_checkpoint = os.path.exists(os.path.join(src, "checkpoint.bin"))
    if not (done or has_checkpoint):
        continue
    dst = os.path.join(stage, t["dir"])
    shutil.rmtree(dst, ignore_errors=True)
    os.makedirs(dst)
    for f in os.listdir(src):
        if f.endswith(".vtu") or f == "walls.csv" or (done and f.startswith("checkpoint")):
            continue
        shutil.copy2(os.path.join(src, f), dst)
    saved += done
    stopped += (not done)
print(f"{saved} finished and {stopped} stopped task folder(s) in {stage}")
PY
  ;;
load)
  plan="$2"
  if [ -d "$stage" ]; then cp -r "$stage"/. "$plan"/; fi
  echo "loaded $(find "$stage" -name run_info.json 2>/dev/null | wc -l) task folder(s) into $plan"
  ;;
*)
  echo "usage: $0 save|load PLAN" >&2
  exit 2
  ;;
esac
