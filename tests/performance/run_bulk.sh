#!/usr/bin/env bash
# Bulk-only benchmark matrix (no contact) through scripts/bench:
#   hertz3d r1, r2  x  np 1, 2  x  linear elastic (1 step)
#   + hertz3d r1    x  np 1, 2  x  Neo-Hookean (2 steps)
# Prints a readable table, then the JSON lines (also appended to
# <runs-dir>/bulk_summary.jsonl).
#
#   tests/performance/run_bulk.sh [--runs-dir DIR] [--repeat N] [--wait-idle SEC] [--quick]
#     --repeat N      run every case N times (run directories ..._rep<i>); the
#                     second table gives the median over the undisturbed repeats
#     --wait-idle SEC before each run wait up to SEC s for an idle machine
#                     (default 120; 0 = no wait). Runs during which other
#                     processes used > max(0.3 s, 10 % of the wall time) of CPU
#                     are marked "*" (disturbed).
#     --quick         r1 only
# Environment: COULOMB_BENCH_MESHES, COULOMB_BUILD_DIR, COULOMB_EXE (see scripts/bench).
# Build first: cmake -S . -B build && cmake --build build -j2
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
bench="$here/scripts/bench"
runs="${COULOMB_BUILD_DIR:-$here/build}/bench-runs"
repeat=1
wait_idle=120
refs=(1 2)
while [ $# -gt 0 ]; do
  case "$1" in
    --runs-dir) runs="$(realpath -m "$2")"; shift 2 ;;
    --repeat) repeat="$2"; shift 2 ;;
    --wait-idle) wait_idle="$2"; shift 2 ;;
    --quick) refs=(1); shift ;;
    -h|--help) sed -n '2,17p' "$0"; exit 0 ;;
    *) echo "run_bulk.sh: unknown argument '$1'" >&2; exit 2 ;;
  esac
done
mkdir -p "$runs"
summary="$runs/bulk_summary.jsonl"
lines=()
failed=0

run() {  # ref np material
  local i tag
  for ((i = 1; i <= repeat; i++)); do
    tag=()
    [ "$repeat" -gt 1 ] && tag=(--tag "rep$i")
    echo "run_bulk: bulk --ref $1 --np $2 --material $3 ${tag[*]}" >&2
    local line
    line="$("$bench" bulk --ref "$1" --np "$2" --material "$3" --runs-dir "$runs" \
      --wait-idle "$wait_idle" "${tag[@]}")" || failed=1
    lines+=("$line")
    printf '%s\n' "$line" >>"$summary"
  done
}

for ref in "${refs[@]}"; do
  for np in 1 2; do run "$ref" "$np" linear; done
done
for np in 1 2; do run 1 "$np" neohookean; done

printf '%s\n' "${lines[@]}" | /usr/bin/python3 -c '
import json, statistics, sys
rows = []
for l in sys.stdin:
    try: rows.append(json.loads(l))
    except ValueError: pass
cols = [("ref", "ref", "{}"), ("np", "np", "{}"), ("material", "material", "{}"), ("status", "status", "{}"),
        ("dofs", "dofs", "{}"), ("Newton", "newton_iterations", "{}"), ("lin.it", "linear_iterations", "{}"),
        ("lin.it/solve", "linear_iterations_per_solve", "{}"), ("assembly s/call", "assembly_s_per_call", "{:.4f}"),
        ("MueLu setup s", "muelu_setup_s", "{:.3f}"), ("solve s", "linear_solve_s_per_solve", "{:.3f}"),
        ("s/Newton", "time_per_newton_s", "{:.3f}"), ("wall s", "wall_s", "{:.2f}"),
        ("max RSS MB", "max_rss_mb", "{:.0f}"), ("other cpu s", "other_cpu_s", "{:.2f}")]
def cell(r, key, fmt):
    v = r.get(key)
    if v is None: return "-"
    if isinstance(v, list): return ",".join(map(str, v)) if len(v) <= 4 else "%d..%d" % (min(v), max(v))
    try: s = fmt.format(v)
    except (ValueError, TypeError): s = str(v)
    return s + ("*" if key == "other_cpu_s" and r.get("disturbed") else "")
def show(title, rows):
    print(title)
    table = [[c[0] for c in cols]] + [[cell(r, k, f) for _, k, f in cols] for r in rows]
    w = [max(len(t[i]) for t in table) for i in range(len(cols))]
    for j, t in enumerate(table):
        print("  ".join(s.rjust(w[i]) for i, s in enumerate(t)))
        if j == 0: print("  ".join("-" * x for x in w))
    print()
show("every run (* = disturbed: other processes used > max(0.3 s, 10 % of the wall time) of CPU)", rows)
groups = {}
for r in rows: groups.setdefault((r.get("ref"), r.get("np"), r.get("material")), []).append(r)
if any(len(g) > 1 for g in groups.values()):
    med = []
    for key, g in groups.items():
        ok = [r for r in g if r.get("status") == "ok"]
        use = [r for r in ok if not r.get("disturbed")] or ok or g
        m = dict(use[0])
        for _, k, _f in cols:
            vals = [r[k] for r in use if isinstance(r.get(k), (int, float)) and not isinstance(r.get(k), bool)]
            if vals and k not in ("ref", "np", "dofs"): m[k] = statistics.median(vals)
        m["status"] = "%d/%d" % (len(use), len(g))
        m["disturbed"] = all(r.get("disturbed") for r in use)
        med.append(m)
    show("median per configuration over the undisturbed ok runs (status = used/all)", med)
'

printf '%s\n' "${lines[@]}"
exit "$failed"
