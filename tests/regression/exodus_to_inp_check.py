#!/usr/bin/python3
"""Checks tests/performance/exodus_to_inp.py (the CalculiX copy of a
quadratic mesh for scripts/bench --order 2 --calculix) on straight-sided
shipped meshes: every element's nodes in CalculiX's order (each mid-side
node at the middle of the corners CalculiX says it sits between, positive
volume), every surface face's nodes (by CalculiX's face label) in the node
set of the same name, the node coordinates as in the Exodus file.

Usage: exodus_to_inp_check.py REPO MESH.e...   (exit 1 with a message on a mismatch)
"""
import os
import sys
import tempfile

import netCDF4
import numpy as np

# CalculiX's mid-side nodes (1-based positions) and the corners they lie between.
MIDS = {
    "C3D20": {9: (1, 2), 10: (2, 3), 11: (3, 4), 12: (4, 1), 13: (5, 6), 14: (6, 7), 15: (7, 8), 16: (8, 5),
              17: (1, 5), 18: (2, 6), 19: (3, 7), 20: (4, 8)},
    "C3D10": {5: (1, 2), 6: (2, 3), 7: (3, 1), 8: (1, 4), 9: (2, 4), 10: (3, 4)},
}
# CalculiX's face labels: corner positions (1-based).
FACES = {
    "C3D20": {"S1": (1, 2, 3, 4), "S2": (5, 8, 7, 6), "S3": (1, 5, 6, 2), "S4": (2, 6, 7, 3), "S5": (3, 7, 8, 4),
              "S6": (4, 8, 5, 1)},
    "C3D10": {"S1": (1, 2, 3), "S2": (1, 4, 2), "S3": (2, 4, 3), "S4": (3, 4, 1)},
}


def fail(message):
    print("exodus_to_inp_check: " + message)
    sys.exit(1)


def read_inp(path):
    nodes, elements, types, nsets, surfaces = {}, {}, {}, {}, {}
    mode, name, pending = None, None, []
    for line in open(path):
        line = line.strip()
        if not line or line.startswith("**"):
            continue
        if line.startswith("*"):
            head = line.upper()
            mode = head.split(",")[0][1:]
            if mode == "ELEMENT":
                name = [p.split("=")[1] for p in line.split(",") if p.strip().upper().startswith("TYPE")][0]
            elif mode == "NSET":
                name = line.split("NSET=")[1].split(",")[0]
                nsets[name] = set()
            elif mode == "SURFACE":
                name = line.split("NAME=")[1].split(",")[0]
                surfaces[name] = []
            continue
        values = [v.strip() for v in line.split(",") if v.strip()]
        if mode == "NODE":
            nodes[int(values[0])] = np.array([float(v) for v in values[1:]])
        elif mode == "ELEMENT":
            pending += [int(v) for v in values]
            if not line.endswith(","):
                elements[pending[0]] = pending[1:]
                types[pending[0]] = name
                pending = []
        elif mode == "NSET":
            nsets[name].update(int(v) for v in values)
        elif mode == "SURFACE":
            surfaces[name].append((int(values[0]), values[1]))
    return nodes, elements, types, nsets, surfaces


def check(repo, mesh):
    with tempfile.TemporaryDirectory() as work:
        inp = os.path.join(work, "mesh.inp")
        if os.system(f"/usr/bin/python3 {repo}/tests/performance/exodus_to_inp.py {mesh} {inp}") != 0:
            fail(f"conversion of {mesh} failed")
        nodes, elements, types, nsets, surfaces = read_inp(inp)
    exo = netCDF4.Dataset(mesh)
    xyz = np.stack([exo.variables[f"coord{c}"][:] for c in "xyz"], axis=1)
    if len(nodes) != len(xyz) or any(np.abs(nodes[i + 1] - xyz[i]).max() > 1e-12 for i in range(len(xyz))):
        fail(f"{mesh}: the node coordinates differ")
    checked = 0
    for e, conn in elements.items():
        kind = types[e]
        if kind not in MIDS:
            fail(f"{mesh}: element {e} is {kind}, expected C3D20 or C3D10")
        x = {k + 1: nodes[n] for k, n in enumerate(conn)}
        for mid, (a, b) in MIDS[kind].items():
            if np.abs(x[mid] - 0.5 * (x[a] + x[b])).max() > 1e-9:
                fail(f"{mesh}: element {e}: node {mid} is not between its corners {a} and {b}")
        # The corner tetrahedron at node 1 (hexahedron: nodes 1, 2, 4, 5).
        a, b, c = (2, 4, 5) if kind == "C3D20" else (2, 3, 4)
        volume = np.dot(np.cross(x[a] - x[1], x[b] - x[1]), x[c] - x[1])
        if volume <= 0:
            fail(f"{mesh}: element {e} has a non-positive volume in CalculiX's order")
        checked += 1
    faces = 0
    for name, entries in surfaces.items():
        if name not in nsets:
            continue
        for e, label in entries:
            corners = {elements[e][k - 1] for k in FACES[types[e]][label]}
            if not corners <= nsets[name]:
                fail(f"{mesh}: surface {name}: face {label} of element {e} has nodes outside node set {name}")
            faces += 1
    if checked == 0 or faces == 0:
        fail(f"{mesh}: nothing checked ({checked} elements, {faces} faces)")
    print(f"{os.path.basename(mesh)}: {checked} elements, {faces} surface faces as CalculiX reads them")


if __name__ == "__main__":
    if len(sys.argv) < 3:
        fail(__doc__)
    for path in sys.argv[2:]:
        check(sys.argv[1], path)
