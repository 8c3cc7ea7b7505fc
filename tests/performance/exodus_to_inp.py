#!/usr/bin/python3
"""A CalculiX mesh file (.inp: *NODE, *ELEMENT per block, *NSET per node set,
*SURFACE TYPE=ELEMENT per side set) from an Exodus II mesh, with the same
node and element numbers (Exodus node 17 = ccx node 17; elements numbered
through the blocks in file order), for the peer harness on meshes it does
not export itself: scripts/bench hertz3d --order 2 --calculix (HEX20 ->
C3D20, TET10 -> C3D10; HEX8, TET4 as the harness' own export).

Usage: exodus_to_inp.py MESH.e OUT.inp   (needs python3-netcdf4)
"""
import sys

import netCDF4
import numpy as np

# Exodus local node order -> CalculiX's (0-based positions in the Exodus
# connectivity). HEX20: Exodus lists the bottom edges, then the vertical
# ones, then the top ones; CalculiX bottom, top, vertical.
CCX_TYPES = {
    ("HEX8", 8): ("C3D8", list(range(8))),
    ("HEX20", 20): ("C3D20", list(range(12)) + list(range(16, 20)) + list(range(12, 16))),
    ("TETRA4", 4): ("C3D4", list(range(4))),
    ("TETRA10", 10): ("C3D10", list(range(10))),
}
# Exodus side (1-based) -> CalculiX face label (the same for the quadratic cells)
FACES = {"C3D8": {1: "S3", 2: "S4", 3: "S5", 4: "S6", 5: "S1", 6: "S2"},
         "C3D4": {1: "S2", 2: "S3", 3: "S4", 4: "S1"}}
FACES["C3D20"] = FACES["C3D8"]
FACES["C3D10"] = FACES["C3D4"]


def names(nc, variable, count):
    if variable not in nc.variables:
        return [f"set{i + 1}" for i in range(count)]
    raw = nc.variables[variable][:]
    return [b"".join(x for x in row if x is not np.ma.masked).decode().strip("\x00 ") for row in raw]


def kind(elem_type, nodes):
    t = elem_type.upper()
    base = "HEX" if t.startswith("HEX") else "TETRA" if t.startswith("TET") else t
    key = (f"{base}{nodes}", nodes)
    if key not in CCX_TYPES:
        raise SystemExit(f"exodus_to_inp: element type {elem_type} with {nodes} nodes is not converted")
    return CCX_TYPES[key]


def lines_of(numbers, per_line=16):
    """CalculiX takes at most 16 entries per data line; continue on the next."""
    text = [str(n) for n in numbers]
    return [", ".join(text[i:i + per_line]) + ("," if i + per_line < len(text) else "")
            for i in range(0, len(text), per_line)]


def convert(exodus, out):
    nc = netCDF4.Dataset(exodus)
    nc.set_auto_mask(False)
    if "coord" in nc.variables:
        xyz = np.array(nc.variables["coord"][:]).T
    else:
        xyz = np.stack([nc.variables[f"coord{c}"][:] for c in "xyz"], axis=1)
    lines = ["** written by tests/performance/exodus_to_inp.py from " + exodus.split("/")[-1], "*NODE, NSET=NALL"]
    lines += [f"{i + 1}, {x:.15g}, {y:.15g}, {z:.15g}" for i, (x, y, z) in enumerate(xyz)]

    blocks = names(nc, "eb_names", len(nc.dimensions["num_el_blk"]))
    ccx_type_of = []  # per element (0-based global), for the side sets
    first = 1
    for b, name in enumerate(blocks):
        connect = nc.variables[f"connect{b + 1}"]
        ccx, order = kind(connect.elem_type, connect.shape[1])
        lines.append(f"*ELEMENT, TYPE={ccx}, ELSET={name}")
        for e, row in enumerate(np.array(connect[:])):
            lines += lines_of([first + e] + [int(row[k]) for k in order])
        ccx_type_of += [ccx] * connect.shape[0]
        first += connect.shape[0]

    if "num_node_sets" in nc.dimensions:
        for s, name in enumerate(names(nc, "ns_names", len(nc.dimensions["num_node_sets"]))):
            lines.append(f"*NSET, NSET={name}")
            lines += lines_of([int(n) for n in nc.variables[f"node_ns{s + 1}"][:]])
    if "num_side_sets" in nc.dimensions:
        for s, name in enumerate(names(nc, "ss_names", len(nc.dimensions["num_side_sets"]))):
            lines.append(f"*SURFACE, NAME={name}, TYPE=ELEMENT")
            for e, side in zip(nc.variables[f"elem_ss{s + 1}"][:], nc.variables[f"side_ss{s + 1}"][:]):
                lines.append(f"{int(e)}, {FACES[ccx_type_of[int(e) - 1]][int(side)]}")
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        raise SystemExit(__doc__)
    convert(sys.argv[1], sys.argv[2])
