#!/usr/bin/env bash
# Hertz contact benchmark matrix through scripts/bench:
#   hertz3d r1, r1.5, r2 at np 1, hertz3d r2 at np 2, hertz2d r1, r2, r3 at np 1
# (--quick: hertz3d r1 at np 1 and 2, hertz2d r1). Prints the JSON lines (also
# appended to <runs-dir>/hertz_summary.jsonl), then a table.
#
#   tests/performance/run_hertz.sh [--runs-dir DIR] [--wait-idle SEC] [--timeout SEC] [--quick] [--calculix]
#     --calculix      also run the CalculiX peer harness (LINMORTAR) for every
#                     np 1 run (same as CALCULIX=1 in the environment); only
#                     if /usr/bin/ccx exists. The CalculiX runs go to
#                     <run dir>/calculix, never into ../shared.
#     --wait-idle SEC before each run wait up to SEC s for an idle machine
#                     (default 60; 0 = no wait). Runs during which other
#                     processes used > max(0.3 s, 10 % of the wall time) of CPU
#                     are marked "*" (disturbed).
#     --timeout SEC   per run, Coulomb and CalculiX each (default 1800)
# Environment: COULOMB_BENCH_MESHES, COULOMB_BUILD_DIR, COULOMB_EXE (see scripts/bench), CALCULIX=1.
# Build first: cmake -S . -B build && cmake --build build -j2
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bench="$here/scripts/bench"
runs="${COULOMB_BUILD_DIR:-$here/build}/bench-runs"
wait_idle=60
timeout=1800
quick=0
calculix="${CALCULIX:-0}"
while [ $# -gt 0 ]; do
  case "$1" in
    --runs-dir) runs="$(realpath -m "$2")"; shift 2 ;;
    --wait-idle) wait_idle="$2"; shift 2 ;;
    --timeout) timeout="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    --calculix) calculix=1; shift ;;
    -h|--help) sed -n '2,19p' "$0"; exit 0 ;;
    *) echo "run_hertz.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
ccx=()
if [ "$calculix" = 1 ]; then
  if [ -x /usr/bin/ccx ]; then ccx=(--calculix); else echo "run_hertz.sh: /usr/bin/ccx missing, no CalculiX runs" >&2; fi
fi
mkdir -p "$runs"
summary="$runs/hertz_summary.jsonl"
lines=()
failed=0

run() {  # case ref np [--calculix]
  echo "run_hertz: $1 --ref $2 --np $3 ${4:-}" >&2
  local line
  line="$("$bench" "$1" --ref "$2" --np "$3" --runs-dir "$runs" --wait-idle "$wait_idle" \
    --timeout "$timeout" ${4:+"$4"})" || failed=1
  lines+=("$line")
  printf '%s\n' "$line" >>"$summary"
  printf '%s\n' "$line"
}

if [ "$quick" = 1 ]; then
  run hertz3d 1 1 "${ccx[@]}"
  run hertz3d 1 2
  run hertz2d 1 1 "${ccx[@]}"
else
  for ref in 1 1.5 2; do run hertz3d "$ref" 1 "${ccx[@]}"; done
  run hertz3d 2 2
  for ref in 1 2 3; do run hertz2d "$ref" 1 "${ccx[@]}"; done
fi

echo
printf '%s\n' "${lines[@]}" | PYTHONPATH="$here/tests/performance" /usr/bin/python3 -c '
import sys
from bench_table import CALCULIX_COST, ccx, cost_columns, print_table, read_rows
rows = read_rows(sys.stdin)
cols = [("case", "case", "{}"), ("ref", "ref", "{}"),
        ("np", "np", "{}"), ("status", "status", "{}")] + cost_columns("step", solve_time=True) + [
        ("p_max err", "p_max_rel_err", "{:+.1%}"),
        ("p0 fit err", "p0_fit_rel_err", "{:+.1%}"),
        ("a fit err", "a_fit_rel_err", "{:+.1%}"),
        ("a bracket err", "a_bracket_rel_err", "{:+.1%}")] + CALCULIX_COST + [
        ("ccx p0 fit err", lambda r: ccx(r, "p0_fit_rel_err"), "{:+.1%}"),
        ("ccx a fit err", lambda r: ccx(r, "a_fit_rel_err"), "{:+.1%}")]
print_table(rows, cols, "")
'
exit "$failed"
