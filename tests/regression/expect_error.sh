#!/usr/bin/env bash
# Runs one bad deck and checks that Coulomb rejects it the way a user needs:
#   (a) a non-zero exit code, within a time limit (no hang);
#   (b) exactly one line starting with "coulomb: error:" in the whole output
#       (stderr and stdout), on stderr, and that line matches REGEX (which
#       names the offending parameter, file, set or block);
#   (c) no result file: DECK_STEM.e must not exist next to the deck copy
#       (a DECK_STEM.e.part is tolerated: it is only ever a partial result).
#
# usage: expect_error.sh --exe COULOMB --workdir DIR [--meshes DIR] [--cdl FILE]...
#                        [--timeout SECONDS] [--arg ARG]... REGEX DECK NP MPIRUN [MPIRUN_ARGS...]
#
# DIR is emptied and the deck copied into it, with "@MESH_DIR@" replaced by
# the --meshes folder; each --cdl FILE.cdl becomes DIR/FILE.e (ncgen), so a
# deck names such a mesh by its bare file name. REGEX is an extended regular
# expression (grep -E). The run is: MPIRUN... -np NP COULOMB DIR/DECK ARG...
# (each --arg, e.g. --check: the same errors before any solve).
# Exit codes: 0 pass, 1 fail, 77 skipped (a tool the test needs is missing).
set -u

exe="" workdir="" meshes="" timeout_seconds=50
cdls=() coulomb_args=()
while [[ $# -gt 0 && $1 == --* ]]; do
  case $1 in
    --exe) exe=$2; shift 2 ;;
    --workdir) workdir=$2; shift 2 ;;
    --meshes) meshes=$2; shift 2 ;;
    --cdl) cdls+=("$2"); shift 2 ;;
    --timeout) timeout_seconds=$2; shift 2 ;;
    --arg) coulomb_args+=("$2"); shift 2 ;;
    *) echo "expect_error.sh: unknown option $1" >&2; exit 1 ;;
  esac
done
if [[ $# -lt 4 || -z $exe || -z $workdir ]]; then
  echo "usage: expect_error.sh --exe COULOMB --workdir DIR [--meshes DIR] [--cdl FILE]... REGEX DECK NP MPIRUN [ARGS...]" >&2
  exit 1
fi
regex=$1 deck_source=$2 np=$3
shift 3
mpirun=("$@")

fail() {
  echo "FAIL: $*"
  failed=1
}

# Fresh working folder in the build tree (guard against emptying anything else).
case $workdir in
  */bad_input/*) ;;
  *) echo "expect_error.sh: refusing to use workdir '$workdir' (must lie under a bad_input/ folder)" >&2; exit 1 ;;
esac
rm -rf -- "$workdir"
mkdir -p -- "$workdir" || exit 1

deck_name=$(basename -- "$deck_source")
deck=$workdir/$deck_name
sed "s|@MESH_DIR@|${meshes}|g" "$deck_source" >"$deck" || exit 1
result=$workdir/${deck_name%.xml}.e

for cdl in "${cdls[@]+"${cdls[@]}"}"; do
  if ! command -v ncgen >/dev/null 2>&1; then
    echo "SKIPPED: ncgen not installed (needed to make $(basename -- "$cdl" .cdl).e; Debian package netcdf-bin)"
    exit 77
  fi
  # A CDL file may ask for another netCDF kind on a line "// ncgen kind: nc4".
  kind=$(sed -n 's|^// ncgen kind: *\([a-z0-9-]*\).*|\1|p' "$cdl" | head -1)
  ncgen -k "${kind:-classic}" -o "$workdir/$(basename -- "$cdl" .cdl).e" "$cdl" || { echo "FAIL: ncgen $cdl"; exit 1; }
done

command=("${mpirun[@]}" -np "$np" "$exe" "$deck" "${coulomb_args[@]+"${coulomb_args[@]}"}")
echo "deck:     $deck_source"
echo "run:      ${command[*]}"
echo "expect:   one line 'coulomb: error: ...' matching /$regex/"

out=$workdir/stdout.txt err=$workdir/stderr.txt
start=$SECONDS
timeout --kill-after=5 "$timeout_seconds" "${command[@]}" >"$out" 2>"$err" </dev/null
status=$?
elapsed=$((SECONDS - start))

echo "----- stdout -----"
cat -- "$out"
echo "----- stderr -----"
cat -- "$err"
echo "------------------"
echo "exit code $status after ${elapsed}s"

failed=0
# (a) non-zero exit, (d) no hang
if [[ $status -eq 124 || $status -eq 137 ]]; then
  fail "no answer within ${timeout_seconds}s (hang?); killed by timeout"
elif [[ $status -eq 0 ]]; then
  fail "exit code 0: the bad deck was accepted"
fi

# (b) exactly one error line in all output, on stderr, naming the culprit
error_lines=$(cat -- "$out" "$err" | grep -c '^coulomb: error:')
stderr_error_lines=$(grep -c '^coulomb: error:' -- "$err")
if [[ $error_lines -ne 1 ]]; then
  fail "expected exactly one line starting with 'coulomb: error:', found $error_lines"
elif [[ $stderr_error_lines -ne 1 ]]; then
  fail "the 'coulomb: error:' line is on stdout, not on stderr"
else
  line=$(grep '^coulomb: error:' -- "$err")
  if ! grep -Eq -- "$regex" <<<"$line"; then
    fail "the error line does not match /$regex/: $line"
  fi
fi
if grep -q 'internal error' -- "$out" "$err"; then
  fail "an internal error was reported (MPI_Abort path) instead of a user error"
fi

# (c) no result file that looks complete
if [[ -e $result ]]; then
  fail "result file $result exists after a failed run"
fi
if [[ -e $result.part ]]; then
  echo "note: partial result $result.part exists (allowed)"
fi

if [[ $failed -ne 0 ]]; then
  exit 1
fi
echo "PASS"
exit 0
