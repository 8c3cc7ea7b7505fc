#!/usr/bin/env bash
# Runs the libFuzzer harnesses of build-fuzz/ (tests/fuzz/CMakeLists.txt) and
# prints, per harness: executions, corpus size before and after, findings.
#
#   tests/fuzz/run_fuzz.sh [--build DIR] [--runs N] [--jobs J] [HARNESS...]
#     --build  the fuzz build folder (default build-fuzz)
#     --runs   executions per harness (default 1000000; ctest's smoke run: 2000;
#              0: only replay the corpus and the past findings, as ctest does for gmsh)
#     HARNESS  deck exodus gmsh (default: all three)
#
# First every minimised input in tests/fuzz/regressions/<harness>/ (past
# findings) is replayed; then the harness runs from a seed corpus built from
# what the project ships (decks, Exodus meshes, gmsh files made from
# exodus_meshes/*.geo) into DIR/corpus/<harness>, which grows from run to run.
# Findings (crash-*, leak-*, timeout-*, oom-*) land in DIR/findings/<harness>/;
# the exit code is non-zero when there is one.
set -uo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
build="$here/build-fuzz" runs=1000000 harnesses=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --build) build=$2; shift 2 ;;
    --runs) runs=$2; shift 2 ;;
    -*) echo "run_fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) harnesses+=("$1"); shift ;;
  esac
done
[[ ${#harnesses[@]} -eq 0 ]] && harnesses=(deck exodus gmsh)

seed() {  # seed <harness> <corpus dir>
  local harness=$1 corpus=$2
  mkdir -p "$corpus"
  case "$harness" in
    deck)
      find "$here/xml" "$here/tests" -name '*.xml' -size -64k -exec cp -t "$corpus" {} + ;;
    exodus)
      find "$here/xml" "$here/exodus_meshes" -name '*.e' -size -64k -exec cp -t "$corpus" {} + ;;
    gmsh)
      # Every format gmsh reads for us: 2.2 and 4.1, ASCII and binary; and order 2.
      local geo format
      for geo in block2d block2d_tri contact_patch2d block3d_tet friction_punch; do
        local d=2
        grep -q 'Volume' "$here/exodus_meshes/$geo.geo" && d=3
        for format in "msh22" "msh41" "msh41 -bin" "msh41 -order 2"; do
          # shellcheck disable=SC2086  # $format is several gmsh arguments
          gmsh -$d -format $format -setnumber n 2 -o "$corpus/$geo.${format// /_}.msh" "$here/exodus_meshes/$geo.geo" \
            >/dev/null 2>&1 || echo "run_fuzz.sh: gmsh could not mesh $geo.geo ($format; seed skipped)" >&2
        done
      done ;;
  esac
}

# Leaks of third-party code that only the harnesses call (each explained there).
export LSAN_OPTIONS="suppressions=$here/tests/fuzz/lsan_fuzz.supp:print_suppressions=0${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
status=0
printf '%-7s %12s %8s %8s %9s %8s\n' harness executions seeds corpus seconds findings
for harness in "${harnesses[@]}"; do
  exe="$build/fuzz_$harness"
  [[ -x $exe ]] || { echo "run_fuzz.sh: $exe is missing (build $build first)" >&2; exit 2; }
  corpus="$build/corpus/$harness" findings="$build/findings/$harness" log="$build/fuzz_$harness.log"
  rm -rf -- "$findings" && mkdir -p "$findings"  # this run's findings only
  [[ -d $corpus ]] || seed "$harness" "$corpus"
  seeds=$(find "$corpus" -type f | wc -l)
  # Past findings must stay fixed.
  regressions=("$here/tests/fuzz/regressions/$harness"/*)
  if [[ -e ${regressions[0]} ]]; then
    if ! "$exe" -rss_limit_mb=2048 -timeout=10 "${regressions[@]}" >"$log.regressions" 2>&1; then
      echo "run_fuzz.sh: $harness: a past finding is back (log: $log.regressions)" >&2
      status=1
    fi
  fi
  # Memory: resident memory and any single allocation are bounded at 2 GiB
  # (a damaged classic netCDF header is refused before netCDF allocates the
  # counts it declares: io/NetcdfHeaderCheck.hpp).
  malloc_limit=2048
  start=$SECONDS
  "$exe" -runs="$runs" -rss_limit_mb=2048 -malloc_limit_mb=$malloc_limit -timeout=10 -max_len=65536 \
         -print_final_stats=1 -artifact_prefix="$findings/" "$corpus" >"$log" 2>&1
  rc=$?
  executions=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
  size=$(find "$corpus" -type f | wc -l)
  found=$(find "$findings" -type f | wc -l)
  printf '%-7s %12s %8s %8s %9s %8s\n' "$harness" "${executions:-?}" "$seeds" "$size" $((SECONDS - start)) "$found"
  if [[ $rc -ne 0 || $found -ne 0 ]]; then
    echo "run_fuzz.sh: $harness: exit $rc; findings in $findings; log $log:" >&2
    grep -E 'ERROR|SUMMARY|terminate|what\(\)' "$log" | head -5 >&2
    status=1
  fi
done
exit $status
