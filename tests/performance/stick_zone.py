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
import sys


def _row(xs):
    return [len(xs), min(xs) if xs else None, max(xs) if xs else None]


def coulomb_stick_zones(path):
    from netCDF4 import Dataset, chartostring
    with Dataset(path) as d:
        d.set_auto_mask(False)
        names = [str(n).strip() for n in chartostring(d.variables["name_nod_var"][:])]
        state = d.variables["vals_nod_var%d" % (names.index("contact_state") + 1)][:]
        x = d.variables["coordx"][:]
        return [_row([float(xi) for xi, s in zip(x, step) if s > 1.5]) for step in state]


def calculix_stick_zones(path, mu):
    """rows per CONTACT result block of a CalculiX .frd (ASCII)"""
    coords, rows, block, name, data = {}, [], None, None, {}
    with open(path, errors="replace") as f:
        for line in f:
            if line.startswith("    2C"):
                block = "coords"
            elif line.startswith("  100CL"):
                block, name, data = "results", None, {}
            elif line.startswith(" -4") and block == "results":
                name = line.split()[1]
            elif line.startswith(" -3"):
                if block == "results" and name == "CONTACT":
                    stick = [coords[n][0] for n, v in data.items()
                             if v[3] > 0 and math.hypot(v[4], v[5]) < 0.99 * mu * v[3]]
                    rows.append(_row(stick))
                block = None
            elif line.startswith(" -1") and (block == "coords" or (block == "results" and name == "CONTACT")):
                values = [float(line[13 + 12 * k:25 + 12 * k]) for k in range((len(line.rstrip()) - 13) // 12)]
                (coords if block == "coords" else data)[int(line[3:13])] = values
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("result")
    parser.add_argument("--frd")
    parser.add_argument("--mu", type=float, default=0.3)
    args = parser.parse_args()
    out = {"stick_zone": coulomb_stick_zones(args.result)}
    if args.frd:
        out["calculix_stick_zone"] = calculix_stick_zones(args.frd, args.mu)
    fmt = lambda r: "%4d [%s, %s]" % (r[0], "-" if r[1] is None else "%.3f" % r[1], "-" if r[2] is None else "%.3f" % r[2])
    for k, row in enumerate(out["stick_zone"]):
        other = out.get("calculix_stick_zone", [])
        print("step %2d  coulomb %-24s calculix %s" % (k + 1, fmt(row), fmt(other[k]) if k < len(other) else "-"),
              file=sys.stderr)
    print(json.dumps(out))


if __name__ == "__main__":
    main()
