#!/usr/bin/env bash
# The smoke suite on a real SLURM scheduler: starts a one-node cluster on this machine
# (installing Debian's slurm-wlm and munge if missing; needs root), submits the suite's plan as
# an array job with `submit.sh`, waits, and checks that the collected summary.csv is
# byte-identical to the serial `verify all --fidelity smoke`. Run by .ci/run and the nightly
# workflow. Usage: scripts/slurm_smoke.sh [VERIFY_BINARY [CASE...]]   (default: builds
# target/debug/verify; every case). `.ci/run` names a few cases: what it tests here is the
# scheduler's round trip; that every case's tasks collect to its serial results, in any order,
# is `verify/tests/plan.rs`'s test.
set -euo pipefail
cd "$(dirname "$0")/.."

if [ "$#" -ge 1 ]; then
  verify=$(realpath "$1")
  shift
else
  cargo build -q -p verify
  verify=$(realpath "${CARGO_TARGET_DIR:-target}/debug/verify")
fi

if ! command -v slurmctld >/dev/null || ! command -v munged >/dev/null; then
  apt-get update -q >/dev/null
  DEBIAN_FRONTEND=noninteractive apt-get install -y -q slurm-wlm munge >/dev/null
fi

work=$(mktemp -d /tmp/verify-slurm.XXXXXX)
host=$(hostname -s)
pids=()
stop() {
  for p in "${pids[@]}"; do kill "$p" 2>/dev/null || true; done
  for p in "${pids[@]}"; do
    # a daemon killed in a container whose PID 1 reaps nothing stays a zombie: wait for
    # either its end or that state, not for kill -0
    for _ in $(seq 50); do
      state=$(awk '/^State:/ {print $2}' "/proc/$p/status" 2>/dev/null || echo gone)
      [ "$state" = gone ] || [ "$state" = Z ] && break
      sleep 0.1
    done
  done
}
trap stop EXIT

# munge: its key comes with the package; without systemd its run folder must be made
mkdir -p /run/munge && chown munge:munge /run/munge && chmod 755 /run/munge
if ! munge -n 2>/dev/null | unmunge >/dev/null 2>&1; then
  runuser -u munge -- munged
fi
munge -n | unmunge | grep -q Success

mem_mb=$(awk '/MemTotal/ {print int($2 / 1024 * 0.9)}' /proc/meminfo)
mkdir -p "$work/state" "$work/spool" "$work/log"
export SLURM_CONF="$work/slurm.conf"
cat >"$SLURM_CONF" <<EOF
ClusterName=verify
SlurmctldHost=$host(127.0.0.1)
SlurmUser=root
AuthType=auth/munge
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_CPU
AccountingStorageType=accounting_storage/none
JobAcctGatherType=jobacct_gather/none
MailProg=/bin/true
ReturnToService=2
StateSaveLocation=$work/state
SlurmdSpoolDir=$work/spool
SlurmctldLogFile=$work/log/slurmctld.log
SlurmdLogFile=$work/log/slurmd.log
SlurmctldPidFile=$work/slurmctld.pid
SlurmdPidFile=$work/slurmd.pid
NodeName=$host NodeAddr=127.0.0.1 CPUs=$(nproc) RealMemory=$mem_mb State=UNKNOWN
PartitionName=main Nodes=$host Default=YES MaxTime=INFINITE State=UP
EOF

slurmctld -D -f "$SLURM_CONF" >"$work/log/slurmctld.out" 2>&1 &
pids+=($!)
slurmd -D -N "$host" -f "$SLURM_CONF" >"$work/log/slurmd.out" 2>&1 &
pids+=($!)
for _ in $(seq 60); do
  scontrol ping 2>/dev/null | grep -q UP && sinfo -h -o %t 2>/dev/null | grep -q idle && break
  sleep 1
done
sinfo -h -o %t | grep -q idle || {
  echo "slurm did not come up" >&2
  cat "$work"/log/* >&2
  exit 1
}

cases=("$@")
if [ "${#cases[@]}" -eq 0 ]; then
  echo "serial: verify all --fidelity smoke"
  "$verify" all --fidelity smoke --threads 2 --out "$work/serial" 2>"$work/log/serial.log"
else
  echo "serial: verify case ${cases[*]} --fidelity smoke"
  "$verify" case "${cases[@]}" --fidelity smoke --threads 2 --out "$work/serial" 2>"$work/log/serial.log"
fi

echo "plan: verify plan suite ${cases[*]} --fidelity smoke, submitted as an array job"
"$verify" plan suite "${cases[@]}" --fidelity smoke --cpus-per-task 1 --time 00:30:00 --out "$work/plan" >/dev/null
read -r array collect < <(bash "$work/plan/submit.sh")
echo "array job $array, collect job $collect"
t0=$(date +%s)
while squeue -h -j "$array,$collect" 2>/dev/null | grep -q .; do
  if [ $(($(date +%s) - t0)) -gt 900 ]; then
    echo "jobs still queued or running after 15 minutes" >&2
    squeue >&2
    exit 1
  fi
  sleep 2
done
echo "all jobs ended after $(($(date +%s) - t0)) s"

ntasks=$(python3 -c "import json,sys; print(len(json.load(open(sys.argv[1]))['tasks']))" "$work/plan/plan.json")
nlogs=$(ls "$work/plan/logs"/task_*.log | wc -l)
[ "$nlogs" -eq "$ntasks" ] || { echo "$nlogs task logs for $ntasks tasks" >&2; exit 1; }
grep -q "summary:" "$work/plan/logs/collect.log" || { cat "$work/plan/logs/collect.log" >&2; exit 1; }
if cmp "$work/serial/summary.csv" "$work/plan/summary.csv"; then
  echo "slurm: $ntasks array tasks collected to the serial summary.csv, byte for byte"
  rm -rf "$work"
else
  echo "slurm: collected summary.csv differs from the serial one (kept in $work)" >&2
  exit 1
fi
