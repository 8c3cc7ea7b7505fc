#!/usr/bin/env bash
# Friction (sliding punch) benchmark matrix through scripts/bench:
#   friction r1 and r2 at np 1, friction r1 at np 2 (--quick: r1 at np 1 only).
# Prints the JSON lines (also appended to <runs-dir>/friction_summary.jsonl),
# then a table.
#
#   tests/performance/run_friction.sh [--runs-dir DIR] [--wait-idle SEC] [--timeout SEC]
#                                     [--quick] [--calculix] [--frictionless]
#     --calculix      also run the CalculiX peer harness (LINMORTAR, mu 0.3) for
#                     every np 1 run (same as CALCULIX=1 in the environment);
#                     only if /usr/bin/ccx exists. The CalculiX runs go to
#                     <run dir>/calculix, never into ../shared.
#     --frictionless  run the deck without its friction law (scripts/bench
#                     --frictionless: Q ~ 0; checks the pipeline, and a reference)
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
extra=()
while [ $# -gt 0 ]; do
  case "$1" in
    --runs-dir) runs="$(realpath -m "$2")"; shift 2 ;;
    --wait-idle) wait_idle="$2"; shift 2 ;;
    --timeout) timeout="$2"; shift 2 ;;
    --quick) quick=1; shift ;;
    --calculix) calculix=1; shift ;;
    --frictionless) extra+=(--frictionless); shift ;;
    -h|--help) sed -n '2,23p' "$0"; exit 0 ;;
    *) echo "run_friction.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
ccx=()
if [ "$calculix" = 1 ]; then
  if [ -x /usr/bin/ccx ]; then ccx=(--calculix); else echo "run_friction.sh: /usr/bin/ccx missing, no CalculiX runs" >&2; fi
fi
mkdir -p "$runs"
summary="$runs/friction_summary.jsonl"
lines=()
failed=0

run() {  # ref np [--calculix]
  echo "run_friction: friction --ref $1 --np $2 ${extra[*]:-} ${3:-}" >&2
  local line
  line="$("$bench" friction --ref "$1" --np "$2" --runs-dir "$runs" --wait-idle "$wait_idle" \
    --timeout "$timeout" "${extra[@]}" ${3:+"$3"})" || failed=1
  lines+=("$line")
  printf '%s\n' "$line" >>"$summary"
  printf '%s\n' "$line"
}

run 1 1 "${ccx[@]}"
if [ "$quick" = 0 ]; then
  run 2 1 "${ccx[@]}"
  run 1 2
fi

echo
printf '%s\n' "${lines[@]}" | PYTHONPATH="$here/tests/performance" /usr/bin/python3 -c '
import sys
from bench_table import CALCULIX_COST, ccx, cost_columns, print_table, read_rows
rows = read_rows(sys.stdin)
def slip(r):
    s, a = r.get("slipping_slave_nodes_end"), r.get("active_slave_nodes_end")
    return None if s is None and a is None else f"{s if s is not None else chr(45)}/{a if a is not None else chr(45)}"
cols = [("ref", "ref", "{}"), ("np", "np", "{}"),
        ("mu", lambda r: "0 (frictionless)" if r.get("frictionless") else r.get("mu"), "{}"),
        ("status", "status", "{}"), ("inc", "increments", "{}")] + cost_columns("inc") + [
        ("P end", "P_end", "{:.1f}"),
        ("Q/P end", "Q_over_P_end", "{:.4f}"),
        ("Q/muP end", "Q_over_muP_end", "{:.4f}"),
        ("gross slip ux", "gross_slip_from_ux", "{:.4g}"),
        ("Q/P sliding", "Q_over_P_sliding_mean", "{:.4f}"),
        ("slip/active", slip, "{}"),
        ] + CALCULIX_COST + [
        ("ccx P end", lambda r: ccx(r, "P_end"), "{:.1f}"),
        ("ccx Q/P end", lambda r: ccx(r, "Q_over_P_end"), "{:.4f}"),
        ("ccx gross slip ux", lambda r: ccx(r, "gross_slip_from_ux"), "{:.4g}")]
print_table(rows, cols, "friction (sliding punch), ")
'
exit "$failed"
