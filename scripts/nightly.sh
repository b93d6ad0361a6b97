#!/usr/bin/env bash
# Nightly accuracy regression: run the standard verification suite into a dated folder and
# compare every metric with the committed baseline. Exit code 4 means some metric got worse
# (the list is printed and written into the folder's summary.md); 0 means none did.
#
# Schedule it with cron, e.g. `0 2 * * * /path/to/repo/scripts/nightly.sh >> nightly.log 2>&1`,
# or use .github/workflows/nightly.yml.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-reports/nightly/$(date +%F)}"
cargo run --release -p verify -- all --out "$out" --compare reference/baseline_standard.csv
