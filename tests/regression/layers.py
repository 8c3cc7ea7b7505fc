#!/usr/bin/python3
"""Fails when a source file includes a layer above its own.

  tests/regression/layers.py [SOURCE_DIR]

The layers and what each may include (docs/architecture.md, "Layers"):
a file of src/coulomb/<layer>/ may include "coulomb/<other>/..." only for
<other> in ALLOWED[<layer>]. Inside the contact wing the same holds for
its folders (CONTACT_ALLOWED): mortar/ (dual basis, segments, clipping) and
laws/ (nodal kernels, active-set rules, friction laws) stand alone,
interface/ (interface, search, normals, the mortar pass) builds on mortar/,
formulation/ on laws/, interface/ and the shared headers of contact/
(settings, contributions), and contact/ itself (the pair, the model) on all.
"""
import os
import re
import sys

ALLOWED = {
    "core": {"core"},
    "mesh": {"core", "mesh"},
    "io": {"core", "mesh", "io"},
    "linalg": {"core", "linalg"},
    "fem": {"core", "mesh", "io", "linalg", "fem"},
    "contact": {"core", "mesh", "io", "linalg", "fem", "contact"},
    "solver": {"core", "mesh", "io", "linalg", "fem", "contact", "solver"},
}
# The contact wing's folders; "base" is contact/ itself. The shared headers
# of contact/ (SHARED) may be included by the formulations.
CONTACT_ALLOWED = {
    "mortar": {"mortar"},
    "laws": {"laws"},
    "interface": {"interface", "mortar"},
    "formulation": {"formulation", "laws", "interface", "mortar", "shared"},
    "base": {"base", "shared", "formulation", "laws", "interface", "mortar"},
}
SHARED = {"ContactSettings.hpp", "ContactContributions.hpp"}


def contact_part(path):
    """'mortar', 'laws', ... for a path under contact/ ('shared' for SHARED)."""
    parts = path.split("/")
    if len(parts) == 2:
        return "shared" if parts[1] in SHARED else "base"
    return parts[1]


INCLUDE = re.compile(r'^\s*#\s*include\s+"coulomb/([^"]+)"')


def violations(root):
    src = os.path.join(root, "src", "coulomb")
    found = []
    for directory, _, files in os.walk(src):
        for name in sorted(files):
            if not name.endswith((".hpp", ".cpp")):
                continue
            path = os.path.join(directory, name)
            rel = os.path.relpath(path, src).replace(os.sep, "/")
            layer = rel.split("/")[0]
            with open(path, encoding="utf-8") as f:
                for number, line in enumerate(f, 1):
                    m = INCLUDE.match(line)
                    if not m:
                        continue
                    target = m.group(1)
                    other = target.split("/")[0]
                    where = f"src/coulomb/{rel}:{number}: includes coulomb/{target}"
                    if layer not in ALLOWED:
                        found.append(f"{where}: '{layer}' is no known layer (add it to {__file__})")
                    elif other not in ALLOWED[layer]:
                        found.append(f"{where}: '{layer}' may not include '{other}'")
                    elif layer == "contact" and other == "contact":
                        mine = contact_part(rel)
                        mine = "base" if mine == "shared" and not rel.endswith(".hpp") else mine
                        allowed = CONTACT_ALLOWED["laws" if mine == "shared" else mine]
                        if contact_part(target) not in allowed:
                            found.append(f"{where}: contact/{mine} may not include contact/{contact_part(target)}")
    return found


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    found = violations(root)
    for line in found:
        print(line)
    checked = sum(len(f) for _, _, f in os.walk(os.path.join(root, "src", "coulomb")))
    print(f"layers: {len(found)} wrong-direction includes in {checked} files")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
