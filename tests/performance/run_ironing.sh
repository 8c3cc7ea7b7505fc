#!/usr/bin/env bash
# Ironing (3D sliding sphere) benchmark matrix through scripts/bench:
#   ironing r1 at np 1 and np 2, ironing r1.5 at np 1 (--quick: r1 at np 1 only).
# Prints the JSON lines (also appended to <runs-dir>/ironing_summary.jsonl),
# then a table. No CalculiX counterpart.
#
#   tests/performance/run_ironing.sh [--runs-dir DIR] [--wait-idle SEC] [--timeout SEC] [--quick]
#     --wait-idle SEC before each run wait up to SEC s for an idle machine
#                     (default 60; 0 = no wait). Runs during which other
#                     processes used > max(0.3 s, 10 % of the wall time) of CPU
#                     are marked "*" (disturbed).
#     --timeout SEC   per run (default 1800)
# Environment: COULOMB_BENCH_MESHES, COULOMB_BUILD_DIR, COULOMB_EXE (see scripts/bench).
# Build first: cmake -S . -B build && cmake --build build -j2
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bench="$here/scripts/bench"
runs="${COULOMB_BUILD_DIR:-$here/build}/bench-runs"
wait_idle=60
timeout=1800
quick=0
while [ $# -gt 0 ]; do
  case "$1" in
    --runs-dir) runs="$(realpath -m "$2")"; shift 2 ;;
    --wait-idle) wait_idle="$2"; shift 2 ;;
    --timeout) timeout="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    -h|--help) sed -n '2,14p' "$0"; exit 0 ;;
    *) echo "run_ironing.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
mkdir -p "$runs"
summary="$runs/ironing_summary.jsonl"
lines=()
failed=0

run() {  # ref np
  echo "run_ironing: ironing --ref $1 --np $2" >&2
  local line
  line="$("$bench" ironing --ref "$1" --np "$2" --runs-dir "$runs" --wait-idle "$wait_idle" \
    --timeout "$timeout")" || failed=1
  lines+=("$line")
  printf '%s\n' "$line" >>"$summary"
  printf '%s\n' "$line"
}

run 1 1
if [ "$quick" = 0 ]; then
  run 1 2
  run 1.5 1
fi

echo
printf '%s\n' "${lines[@]}" | PYTHONPATH="$here/tests/performance" /usr/bin/python3 -c '
import sys
from bench_table import cost_columns, print_table, read_rows
rows = read_rows(sys.stdin)
def stick_slip(r):
    st, sl = r.get("stick_per_increment"), r.get("slip_per_increment")
    return None if not st or not sl else f"{sl[-1]}/{st[-1]}"
cols = [("ref", "ref", "{}"), ("np", "np", "{}"),
        ("status", "status", "{}"), ("inc", "increments", "{}"),
        ("cutbacks", "cutbacks", "{}")] + cost_columns("inc") + [
        ("P press", "P_after_step1", "{:.1f}"),
        ("P end", "P_end", "{:.1f}"),
        ("Q/P end", "Q_over_P_end", "{:.4f}"),
        ("gross slip ux", "gross_slip_from_ux", "{:.4g}"),
        ("Q/P sliding", "Q_over_P_sliding_mean", "{:.4f}"),
        ("slip/stick end", stick_slip, "{}"),
        ("patch shift", "patch_shift", "{:.4f}")]
print_table(rows, cols, "ironing (3D sliding sphere), ")
'
exit "$failed"
