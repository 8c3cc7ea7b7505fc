#!/usr/bin/python3
"""Fails when a source file includes a layer above its own.

  tests/regression/layers.py [SOURCE_DIR]

The layers and what each may include (docs/architecture.md, "Layers"):
a file of src/coulomb/<layer>/ may include "coulomb/<other>/..." only for
<other> in ALLOWED[<layer>]. Inside the contact wing, the formulations
(contact/formulation/) see the kernels and the contributions but not the
pair or the model that drive them, and the kernels and mortar files do not
see the formulations.
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
# contact/ files that drive the formulations (may include contact/formulation/).
CONTACT_DRIVERS = re.compile(r"^contact/(ContactPair|ContactModel)[A-Za-z]*\.(hpp|cpp)$")
FORMULATION_MAY_NOT = re.compile(r"^contact/(ContactPair|ContactModel)[A-Za-z]*\.hpp$")
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
                    elif rel.startswith("contact/formulation/") and FORMULATION_MAY_NOT.match(target):
                        found.append(f"{where}: a formulation may not include the pair or the model that drive it")
                    elif (layer == "contact" and not rel.startswith("contact/formulation/")
                          and target.startswith("contact/formulation/") and not CONTACT_DRIVERS.match(rel)):
                        found.append(f"{where}: only the pair and the model include the formulations")
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
