#!/usr/bin/python3
"""Check that zoo cases converged, passed their checks and took the same Newton iterations.

    /usr/bin/python3 tests/zoo/same_iterations.py OUT/zoo.jsonl case1 case2 ...

The units cases (units_patch_3d_mm, _m, _kN) are one problem in three unit
systems: a convergence test measured against the problem's force scale
gives the same iterates in each, so their Newton counts must be equal.
Exit 0 when they are, 1 otherwise (one line saying why).
"""
import json
import sys

path, cases = sys.argv[1], sys.argv[2:]
runs = {}
with open(path) as f:
    for line in f:
        d = json.loads(line)
        runs[d["case"]] = d
bad = [c for c in cases if c not in runs or not runs[c].get("converged") or not (runs[c].get("check") or {}).get("passed")]
if bad:
    print("same_iterations: not converged or check failed: " + ", ".join(bad))
    sys.exit(1)
counts = {c: runs[c]["newton"] for c in cases}
print("same_iterations: Newton iterations " + ", ".join(f"{c} {n}" for c, n in counts.items()))
sys.exit(0 if len(set(counts.values())) == 1 else 1)
