#!/usr/bin/python3
"""Small Exodus II reader shared by the zoo check scripts (tests/zoo/*_check.py).

    import os, sys
    sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
    import zoo_exodus as zx

    r = zx.open_result(CASE, sys.argv)      # exits 2 (with a JSON line) when unreadable
    r.glob("reaction_top_x")               # numpy array, one value per written step
    r.glob_last("reaction_top_x")          # the last written step
    r.nodal("contact_pressure")            # nodal field at the last step (or step=k, 1-based)
    r.node_set("slave")                    # 0-based node indices
    r.coords                               # (num_nodes x dim) reference coordinates
    zx.report(CASE, quantity, value, expected, tolerance, relative=True, **extra)
                                           # prints the one JSON line, exits 0 / 1

Only completed steps are in a result; a run that failed leaves NAME.e.part
(the check is still given NAME.e, which then does not exist: exit 2).
Needs numpy and netCDF4: run with /usr/bin/python3.
"""
import json
import math
import os
import sys

sys.dont_write_bytecode = True  # no __pycache__ in the source tree


def _names(ds, var):
    """the strings of an Exodus name array (char [n][len]), each cut at its first NUL
    (the bytes after it are not always cleared)"""
    if var not in ds.variables:
        return []
    v = ds.variables[var]
    v.set_auto_chartostring(False)
    names = []
    for row in v[:]:
        raw = b"".join(c if isinstance(c, bytes) else bytes([c]) for c in row.tolist())
        names.append(raw.split(b"\0", 1)[0].decode("latin-1").strip())
    return names


class Result:
    """The whole of one Coulomb result file, read eagerly (the zoo meshes are small)."""

    def __init__(self, path):
        import numpy as np
        from netCDF4 import Dataset
        self.path = path
        with Dataset(path) as ds:
            ds.set_auto_mask(False)
            self.dim = ds.dimensions["num_dim"].size
            n = ds.dimensions["num_nodes"].size
            self.num_nodes = n
            self.num_elements = ds.dimensions["num_elem"].size if "num_elem" in ds.dimensions else 0
            self.coords = np.zeros((n, self.dim))
            for i, c in enumerate("xyz"[: self.dim]):
                self.coords[:, i] = ds.variables["coord" + c][:]
            self.times = np.array(ds.variables["time_whole"][:], dtype=float) if "time_whole" in ds.variables \
                else np.zeros(0)
            self.global_names = _names(ds, "name_glo_var")
            self._glo = np.array(ds.variables["vals_glo_var"][:], dtype=float).reshape(len(self.times), -1) \
                if self.global_names and len(self.times) else np.zeros((0, len(self.global_names)))
            self.nodal_names = _names(ds, "name_nod_var")
            self._nod = {name: np.array(ds.variables[f"vals_nod_var{j + 1}"][:], dtype=float)
                         for j, name in enumerate(self.nodal_names)}
            self.sets = {}
            for j, name in enumerate(_names(ds, "ns_names")):
                var = f"node_ns{j + 1}"
                if var in ds.variables:
                    self.sets[name] = np.array(ds.variables[var][:], dtype=int) - 1

    @property
    def steps(self):
        return len(self.times)

    def glob(self, name):
        """one value per written step"""
        if name not in self.global_names:
            raise KeyError(f"{self.path}: no global variable '{name}' (have: {', '.join(self.global_names)})")
        return self._glo[:, self.global_names.index(name)]

    def glob_last(self, name):
        return float(self.glob(name)[-1])

    def nodal(self, name, step=None):
        """the nodal field at `step` (1-based; default the last written step)"""
        if name not in self._nod:
            raise KeyError(f"{self.path}: no nodal variable '{name}' (have: {', '.join(self.nodal_names)})")
        k = self.steps - 1 if step is None else step - 1
        return self._nod[name][k]

    def node_set(self, name):
        if name not in self.sets:
            raise KeyError(f"{self.path}: no node set '{name}' (have: {', '.join(self.sets)})")
        return self.sets[name]


def _emit(record, code):
    print(json.dumps(record))
    sys.exit(code)


def open_result(case, argv):
    """Result of argv[1]; on any failure to read it prints the JSON line and exits 2."""
    if len(argv) < 2:
        _emit({"case": case, "passed": False, "error": "usage: %s RESULT.e" % os.path.basename(argv[0])}, 2)
    path = argv[1]
    if not os.path.exists(path):
        why = "no result file"
        if os.path.exists(path + ".part"):
            why += " (only %s.part: the run failed)" % os.path.basename(path)
        _emit({"case": case, "passed": False, "error": why + ": " + path}, 2)
    try:
        r = Result(path)
    except Exception as e:  # noqa: BLE001  (any reading failure is the same outcome)
        _emit({"case": case, "passed": False, "error": f"cannot read {path}: {e}"}, 2)
    if r.steps == 0:
        _emit({"case": case, "passed": False, "error": f"{path}: no time step written"}, 2)
    return r


def connectivities(path):
    """the connectivity of every element block of the result file: arrays of
    0-based node indices, one row per cell"""
    import numpy as np
    from netCDF4 import Dataset
    with Dataset(path) as ds:
        ds.set_auto_mask(False)
        return [np.array(ds.variables[name][:], dtype=int) - 1 for name in ds.variables if name.startswith("connect")]


def side_weights(path, nodes, x, y):
    """int N_j ds per node (0-based) over the cell sides on a 2D surface, at the
    coordinates x, y (arrays by node): a side between two consecutive corners of a
    cell (the first 3 or 4 connectivity entries) whose corners are both in
    `nodes`; h/2 to each corner (QUAD4, TRI3), or h/6 to each corner and 2h/3 to
    the side's mid node (QUAD8, QUAD9, TRI6: the mid nodes follow the corners in
    side order)"""
    import math
    inside = set(int(i) for i in nodes)
    weight, seen = {}, set()
    for conn in connectivities(path):
        corners = 4 if conn.shape[1] in (4, 8, 9) else 3
        quadratic = conn.shape[1] > corners
        for cell in conn:
            for k in range(corners):
                a, b = int(cell[k]), int(cell[(k + 1) % corners])
                if a not in inside or b not in inside or (min(a, b), max(a, b)) in seen:
                    continue
                seen.add((min(a, b), max(a, b)))
                h = math.hypot(x[a] - x[b], y[a] - y[b])
                ends = ((a, h / 6), (b, h / 6), (int(cell[corners + k]), 2 * h / 3)) if quadratic else \
                    ((a, h / 2), (b, h / 2))
                for j, w in ends:
                    weight[j] = weight.get(j, 0.0) + w
    return weight


def fail_read(case, message):
    """a result that lacks what the check needs (a variable, a set): exit 2"""
    _emit({"case": case, "passed": False, "error": message}, 2)


def report(case, quantity, value, expected, tolerance, relative=True, condition=None, **extra):
    """Prints the check's JSON line and exits 0 when |value - expected| <= tolerance
    (relative: |value - expected| / |expected|) and `condition` (a (bool, text)
    pair for a second requirement, e.g. every active node slipping) holds, else 1."""
    if relative and expected != 0:
        error = abs(value - expected) / abs(expected)
    else:
        error = abs(value - expected)
    passed = bool(math.isfinite(value) and error <= tolerance)
    record = {"case": case, "quantity": quantity, "value": value, "expected": expected, "error": error,
              "tolerance": tolerance, "relative": bool(relative), "passed": passed}
    if condition is not None:
        record["condition"] = condition[1]
        record["condition_met"] = bool(condition[0])
        record["passed"] = passed = passed and bool(condition[0])
    record.update(extra)
    _emit(record, 0 if passed else 1)
