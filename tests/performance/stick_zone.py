#!/usr/bin/python3
"""Stick zone of the sliding punch per load step, Coulomb and CalculiX.

  tests/performance/stick_zone.py RESULT.e [--frd CALCULIX.frd] [--mu MU]

Prints one line of JSON {"stick_zone": [...], "calculix_stick_zone": [...]}:
one row [stick nodes, x_min, x_max] per written step (x: the sliding
direction; x_min/x_max null when no node sticks), and a table on stderr.

Coulomb: the nodes with contact_state == 2 (stick) in RESULT.e.
CalculiX writes no stick/slip state, so a contact node (CPRESS > 0) of its
CONTACT block (*CONTACT FILE CDIS, CSTR in the harness) counts as sticking
while its shear is below the cone by more than 1 %: |CSHEAR| < 0.99 mu CPRESS.

Why: the issue expected the stick zone to shrink from both edges inward; on
this punch both codes show it retreating towards the trailing edge (the
pressing already slips the x edges outward, the pull unloads the trailing
one), which this table shows side by side (tests/performance/README.md).
"""
import argparse
import json
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the (read-only) shared harness folder
HERE = os.path.dirname(os.path.realpath(__file__))
sys.path.insert(0, os.path.normpath(os.path.join(HERE, "..", "..", "..", "shared", "bench", "calculix")))
from bench_calculix import FRICTION_MU  # noqa: E402
from hertz_post import _names  # noqa: E402


def _row(xs):
    return [len(xs), min(xs) if xs else None, max(xs) if xs else None]


def _read(path):
    """x coordinates (by node number - 1) and contact_state per written step"""
    from netCDF4 import Dataset
    with Dataset(path) as d:
        d.set_auto_mask(False)
        state = d.variables["vals_nod_var%d" % (_names(d, "name_nod_var").index("contact_state") + 1)][:]
        return d.variables["coordx"][:], state


def coulomb_stick_zones(path):
    x, state = _read(path)
    return [_row([float(xi) for xi, s in zip(x, step) if s > 1.5]) for step in state]


def calculix_stick_zones(frd, result, mu=FRICTION_MU):
    """rows per CONTACT block of CalculiX's .frd (ccxbench.parse_frd); node
    numbers are those of the Coulomb result's mesh (the peer benchmark's
    Exodus and .inp meshes number nodes alike)"""
    import ccxbench
    x, _ = _read(result)
    rows = []
    for block in ccxbench.parse_frd(frd):
        k = {name: i for i, name in enumerate(block["comps"])}
        p, s1, s2 = k["CPRESS"], k["CSHEAR1"], k["CSHEAR2"]
        rows.append(_row([float(x[n - 1]) for n, v in block["data"].items()
                          if v[p] > 0 and math.hypot(v[s1], v[s2]) < 0.99 * mu * v[p]]))
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("--frd")
    parser.add_argument("--mu", type=float, default=FRICTION_MU)
    args = parser.parse_args()
    out = {"stick_zone": coulomb_stick_zones(args.result)}
    if args.frd:
        out["calculix_stick_zone"] = calculix_stick_zones(args.frd, args.result, args.mu)
    fmt = lambda r: "%4d [%s, %s]" % (r[0], "-" if r[1] is None else "%.3f" % r[1], "-" if r[2] is None else "%.3f" % r[2])
    for k, row in enumerate(out["stick_zone"]):
        other = out.get("calculix_stick_zone", [])
        print("step %2d  coulomb %-24s calculix %s" % (k + 1, fmt(row), fmt(other[k]) if k < len(other) else "-"),
              file=sys.stderr)
    print(json.dumps(out))


if __name__ == "__main__":
    main()
