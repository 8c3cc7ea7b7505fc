#!/usr/bin/env bash
# A result written to a full disk: xml/block_compression.xml with its
# output on a 300 KiB tmpfs (room for about three of its four steps). Checks:
# exit code non-zero; one "coulomb: error:" line naming the file, the full
# disk and the steps kept; no complete-looking result; the .part file opens
# (coulomb_exodiff reads it) with the steps written before the failure.
# Needs a tmpfs mount (root with CAP_SYS_ADMIN); skipped (exit 77) without.
#
# usage: disk_full.sh COULOMB EXODIFF DECK WORKDIR
set -u
exe=$1 exodiff=$2 deck_source=$3 workdir=$4
mkdir -p -- "$workdir" || exit 1
disk=$workdir/disk
mountpoint -q "$disk" && umount "$disk"
rm -rf -- "$disk" && mkdir -p -- "$disk" || exit 1
if ! mount -t tmpfs -o size=300k tmpfs "$disk" 2>/dev/null; then
  echo "disk_full.sh: cannot mount a tmpfs here (not root?): skipped"
  exit 77
fi
trap 'umount "$disk"' EXIT
deck=$workdir/block.xml
sed "s|\.\./exodus_meshes|$(cd "$(dirname "$deck_source")/../exodus_meshes" && pwd)|" "$deck_source" >"$deck" || exit 1
"$exe" "$deck" -o "$disk/block.e" >"$workdir/run.log" 2>&1
rc=$?
errors=$(grep -c "^coulomb: error:" "$workdir/run.log")
line=$(grep "^coulomb: error:" "$workdir/run.log")
echo "exit $rc: $line"
[[ $rc -ne 0 ]] || { echo "FAILED: exit code 0 on a full disk" >&2; exit 1; }
[[ $errors -eq 1 ]] || { echo "FAILED: $errors error lines" >&2; exit 1; }
for part in "$disk/block.e.part" "disk holding it is full" "keeps the steps written before"; do
  [[ $line == *"$part"* ]] || { echo "FAILED: the message does not say '$part'" >&2; exit 1; }
done
[[ ! -e $disk/block.e ]] || { echo "FAILED: a complete-looking block.e was left" >&2; exit 1; }
read_back=$("$exodiff" "$disk/block.e.part" "$disk/block.e.part" 2>&1 | sed -n 's/^coulomb_exodiff: \([0-9]*\) steps.*/\1/p')
[[ -n $read_back && $read_back -ge 1 ]] || { echo "FAILED: the .part file does not read back ($read_back)" >&2; exit 1; }
echo "$read_back converged steps kept and read back"
