#!/usr/bin/env bash
# Runs every command of docs/tutorial.md, as a reader would, so that the
# tutorial cannot drift from what works (ctest Tutorial.commands).
#
# usage: tutorial.sh SOURCE_DIR BUILD_DIR WORKDIR
#
# The commands are the ```sh blocks of the tutorial, in order, in one bash
# (set -e: the first failing command fails the test; `cd` carries over), run
# from WORKDIR, which is emptied and given the repository's layout as a
# reader sees it: scripts/ and examples/ link to the sources, build/ to
# BUILD_DIR. ```text blocks are output shown, never run. mpirun may run as
# root and oversubscribe (OpenMPI's environment switches), so the tutorial
# shows the plain command. Fails too when the tutorial has no command.
set -euo pipefail
source_dir=$1 build_dir=$2 workdir=$3
case $workdir in
  */tutorial*) ;;
  *) echo "tutorial.sh: refusing to empty '$workdir' (must be a tutorial folder)" >&2; exit 1 ;;
esac
if ! command -v pvpython >/dev/null || ! command -v xvfb-run >/dev/null; then
  echo "SKIPPED: pvpython or xvfb-run not installed (the tutorial ends with scripts/render)"
  exit 77
fi
rm -rf -- "$workdir"
mkdir -p -- "$workdir"
ln -s "$source_dir/scripts" "$workdir/scripts"
ln -s "$source_dir/examples" "$workdir/examples"
ln -s "$build_dir" "$workdir/build"

commands=$workdir/commands.sh
awk '/^```sh$/ {inside = 1; next} /^```/ {inside = 0; next} inside' "$source_dir/docs/tutorial.md" > "$commands"
count=$(grep -c -v -E '^[[:space:]]*(#|$)' "$commands" || true)
echo "tutorial: $count commands from docs/tutorial.md"
[ "$count" -gt 0 ] || { echo "FAIL: no command found in docs/tutorial.md"; exit 1; }

export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export COULOMB_BUILD_DIR=$build_dir
cd "$workdir"
bash -e -x "$commands"
echo "PASS: all $count commands of docs/tutorial.md ran"
