#!/usr/bin/env bash
# A run stopped by SIGTERM (core/Interrupt.hpp): the sliding punch
# (xml/friction_punch.xml, its 24 steps refined to 480 so that it runs for
# seconds) gets SIGTERM on every rank at a random moment, REPEAT times, the
# way a batch system stops a job. Each time: exit code non-zero; one console
# line "interrupted by SIGTERM ... keeps the N converged steps up to t = T as
# <file>.part" (or "keeps no step yet"); no complete-looking result file; the .part file opens
# (coulomb_exodiff reads every step) and holds exactly the N steps.
#
# usage: signal_stop.sh COULOMB EXODIFF DECK WORKDIR NP REPEAT MPIRUN [ARGS...]
set -u
exe=$1 exodiff=$2 deck_source=$3 workdir=$4 np=$5 repeat=$6
shift 6
rm -rf -- "$workdir" && mkdir -p -- "$workdir" || exit 1
deck=$workdir/punch.xml
sed -e "s|\.\./exodus_meshes|$(cd "$(dirname "$deck_source")/../exodus_meshes" && pwd)|" \
    -e 's|<Parameter name="Number of Steps" type="int" value="24"/>|<Parameter name="Number of Steps" type="int" value="480"/>|' \
    "$deck_source" >"$deck" || exit 1
grep -q 'value="480"' "$deck" || { echo "signal_stop.sh: the deck's Number of Steps was not found" >&2; exit 1; }
for ((k = 1; k <= repeat; ++k)); do
  rm -f -- "$workdir"/punch.e "$workdir"/punch.e.part
  "$@" -np "$np" "$exe" "$deck" >"$workdir/run.log" 2>&1 &
  launcher=$!
  # A random moment between 0.5 and 2.5 s (setup takes ~0.3 s).
  sleep "$(awk -v s=$RANDOM 'BEGIN { printf "%.2f", 0.5 + 2.0 * s / 32767 }')"
  # The ranks, not the launcher (mpirun would kill the job): its children.
  pkill -TERM -P "$launcher" || { echo "run $k: no rank to signal (finished early?)" >&2; exit 1; }
  wait "$launcher"
  rc=$?
  line=$(grep "coulomb: error: interrupted by SIGTERM" "$workdir/run.log")
  if [[ $rc -eq 143 && -z $line && ! -e $workdir/punch.e.part && ! -e $workdir/punch.e ]]; then
    # Before main() installed the handler (mpirun still starting): the default action, nothing written.
    echo "run $k: SIGTERM before the run started: exit $rc, no file"
    continue
  fi
  if [[ $rc -eq 0 || -z $line ]]; then
    echo "run $k: exit code $rc, message: '${line}'" >&2
    tail -5 "$workdir/run.log" >&2
    exit 1
  fi
  [[ -e $workdir/punch.e ]] && { echo "run $k: a complete-looking punch.e was left" >&2; exit 1; }
  steps=$(sed -n 's/.*keeps the \([0-9]*\) converged steps.*/\1/p' <<<"$line")
  [[ $line == *"keeps no step yet"* ]] && steps=0
  read_back=$("$exodiff" "$workdir/punch.e.part" "$workdir/punch.e.part" 2>&1 |
              sed -n -e 's/^coulomb_exodiff: \([0-9]*\) steps.*/\1/p' -e 's/^coulomb_exodiff: no time steps.*/0/p')
  if [[ -z $steps || $read_back != "$steps" ]]; then
    echo "run $k: the message says $steps steps, the file holds '${read_back}'" >&2
    exit 1
  fi
  echo "run $k: exit $rc, $steps complete steps kept and read back"
done
