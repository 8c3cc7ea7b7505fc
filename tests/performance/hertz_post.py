#!/usr/bin/python3
"""Hertz post-processing of a Coulomb Exodus result (hertz2d / hertz3d).

  tests/performance/hertz_post.py RESULT.e --case hertz2d|hertz3d [--profile] [--step K]

Prints one line of JSON with the accuracy keys of the CalculiX peer harness
(../shared/bench/calculix/ccxbench.py, analyze_hertz and hertz_2d/hertz_3d;
definitions in ../shared/bench/calculix/README.md), evaluated on the LAST
time step of the result (or step K, 1-based):

  P (3D) / P_per_length (2D)   |reaction_top_z| / |reaction_top_y| (global
                               variables; the 2D model has unit thickness)
  E_star                       1 / ((1-nu1^2)/E1 + (1-nu2^2)/E2) = E / (2 (1 - nu^2))
  a_hertz, p0_hertz            Hertz at the measured load, R = 10:
                                 3D: a = (3 P R / (4 E*))^(1/3), p0 = 3 P / (2 pi a^2)
                                 2D: a = sqrt(4 P' R / (pi E*)), p0 = 2 P' / (pi a)
  p_max, p_max_rel_err         largest nodal contact_pressure on the slave
                               node set, p_max / p0_hertz - 1
  r_at_p_max                   smallest r among the nodes carrying p_max
  active                       slave nodes with p > 1e-6 p_max (as ccxbench:
                               activity is judged from the pressure);
                               active_slave_nodes = their number, a_active =
                               their largest r
  a_fit, p0_fit (+ _rel_err)   least squares of p^2 = p0^2 (1 - r^2/a^2), i.e.
                               a straight line p^2 = c0 + c1 r^2 with
                               p0 = sqrt(c0), a = sqrt(-c0/c1), on the active
                               nodes with r <= 0.8 a_active (all active nodes
                               if none)
  a_line_last_active           largest r of an active slave node on the +x line
  a_line_first_inactive        smallest r > a_line_last_active of an inactive
                               (p <= tol, r > 0) slave node on the +x line
  a_bracket_mid (+ _rel_err)   their mean
  max_penetration              max(0, max(-contact_gap)) over the active nodes
                               (ccxbench: -min COPEN over the active nodes)

r: 3D r = sqrt(x^2 + y^2), +x line = nodes with |y| < 1e-9, x >= 0;
   2D r = |x| (the contact line lies along x at y ~ 0), +x line = slave
   nodes with x >= 0 (ccxbench, on its 3D slab: the z = 0 face, x >= 0).
Coordinates are the reference coordinates (coordx/y/z) as in the .frd/.inp.

Coulomb extras (not in ccxbench): contact_force (|contact_force_<pair>_axis|)
and its relative difference to the reaction, active_nodes_state (slave nodes
with contact_state = 1), contact_active_nodes (the global variable),
line_nonmonotone (number of active +x-line nodes whose pressure is higher
than at the previous, smaller-r line node: pressure oscillations),
min_pressure (most negative nodal pressure on the slave set, tension).

Needs numpy and netCDF4: run with /usr/bin/python3 (Debian python3-netcdf4).
"""
import argparse
import json
import math
import sys

E = 210000.0   # both bodies, MPa (ccxbench.E)
NU = 0.3       # ccxbench.NU
R_INDENTER = 10.0  # ccxbench.CASES[...]["R"]
CASES = ("hertz2d", "hertz3d")


# ------------------------------------------------------------------ Hertz
def e_star(E1=E, nu1=NU, E2=E, nu2=NU):
    return 1.0 / ((1 - nu1 ** 2) / E1 + (1 - nu2 ** 2) / E2)


def hertz_3d(P, R=R_INDENTER):
    """sphere on a half space: (a, p0) for the total normal force P"""
    es = e_star()
    a = (3.0 * P * R / (4.0 * es)) ** (1.0 / 3.0)
    return a, 3.0 * P / (2.0 * math.pi * a * a)


def hertz_2d(P_line, R=R_INDENTER):
    """cylinder on a half space, plane strain: (a, p0) for the force per unit length"""
    es = e_star()
    a = math.sqrt(4.0 * P_line * R / (math.pi * es))
    return a, 2.0 * P_line / (math.pi * a)


def hertz(case, load):
    return hertz_3d(load) if case == "hertz3d" else hertz_2d(load)


def fit_hertz(rs, ps):
    """least squares of p^2 = p0^2 (1 - r^2/a^2) -> (a, p0) or None (ccxbench._fit_hertz)"""
    n = len(rs)
    if n < 3:
        return None
    x = [r * r for r in rs]
    y = [p * p for p in ps]
    mx, my = sum(x) / n, sum(y) / n
    sxx = sum((xi - mx) ** 2 for xi in x)
    if sxx <= 0:
        return None
    slope = sum((xi - mx) * (yi - my) for xi, yi in zip(x, y)) / sxx
    c0 = my - slope * mx
    if slope >= 0 or c0 <= 0:
        return None
    return math.sqrt(-c0 / slope), math.sqrt(c0)


# ------------------------------------------------------------------ Exodus
def _names(ds, var):
    from netCDF4 import chartostring
    if var not in ds.variables:
        return []
    return [str(s).strip() for s in chartostring(ds.variables[var][:])]


def read_result(path, step=None):
    """dict with coords (n x 3), node sets {name: 0-based indices}, the global
    and nodal variables of one time step (default: the last), times."""
    import numpy as np
    from netCDF4 import Dataset
    with Dataset(path) as ds:
        ds.set_auto_mask(False)
        n = ds.dimensions["num_nodes"].size
        coords = np.zeros((n, 3))
        for i, c in enumerate("xyz"):
            if "coord" + c in ds.variables:
                coords[:, i] = ds.variables["coord" + c][:]
        times = ds.variables["time_whole"][:] if "time_whole" in ds.variables else np.zeros(0)
        nt = len(times)
        if nt == 0:
            raise RuntimeError(f"{path}: no time step written")
        k = nt - 1 if step is None else step - 1
        glo = {}
        gnames = _names(ds, "name_glo_var")
        if gnames:
            vals = ds.variables["vals_glo_var"][k]
            glo = {name: float(v) for name, v in zip(gnames, vals)}
        nod = {}
        for j, name in enumerate(_names(ds, "name_nod_var")):
            nod[name] = np.array(ds.variables[f"vals_nod_var{j + 1}"][k], dtype=float)
        sets = {}
        for j, name in enumerate(_names(ds, "ns_names")):
            var = f"node_ns{j + 1}"
            if var in ds.variables:
                sets[name] = np.array(ds.variables[var][:], dtype=int) - 1
        dim = ds.dimensions["num_dim"].size
        return {"coords": coords, "sets": sets, "glo": glo, "nod": nod, "times": list(map(float, times)),
                "step": k + 1, "dim": dim, "nodes": n, "elements": ds.dimensions["num_elem"].size}


# ------------------------------------------------------------------ analysis
def slave_profile(case, res):
    """[(r, p, gap, state, on_line, node index)] of the slave node set"""
    nod = res["nod"]
    if "slave" not in res["sets"]:
        raise RuntimeError("result has no node set 'slave'")
    if "contact_pressure" not in nod:
        raise RuntimeError("result has no nodal variable 'contact_pressure' (no contact?)")
    gap = nod.get("contact_gap")
    state = nod.get("contact_state")
    pts = []
    for i in res["sets"]["slave"]:
        x, y, _z = res["coords"][i]
        if case == "hertz3d":
            r = math.hypot(x, y)
            on_line = abs(y) < 1e-9 and x >= -1e-12
        else:
            r = abs(x)
            on_line = x >= -1e-12
        pts.append((r, float(nod["contact_pressure"][i]), float(gap[i]) if gap is not None else 0.0,
                    float(state[i]) if state is not None else float("nan"), on_line, int(i)))
    return pts


def analyze(case, res):
    glo = res["glo"]
    axis = "z" if case == "hertz3d" else "y"
    key = f"reaction_top_{axis}"
    if key not in glo:
        raise RuntimeError(f"result has no global variable '{key}'")
    load = abs(glo[key])
    out = {"time": res["times"][res["step"] - 1], "nodes": res["nodes"], "elements": res["elements"],
           "slave_nodes": len(res["sets"].get("slave", ()))}
    if case == "hertz3d":
        out["P"] = load
    else:
        out["thickness"] = 1.0
        out["P_per_length"] = load
    a_h, p0_h = hertz(case, load)
    out.update({"a_hertz": a_h, "p0_hertz": p0_h, "E_star": e_star()})

    prof = slave_profile(case, res)
    pmax = max(p for _, p, *_ in prof)
    tol = 1e-6 * max(pmax, 1e-30)
    act = [(r, p) for r, p, *_ in prof if p > tol]
    out["p_max"] = pmax
    out["p_max_rel_err"] = pmax / p0_h - 1.0
    out["r_at_p_max"] = min(r for r, p, *_ in prof if p == pmax)
    out["active_slave_nodes"] = len(act)
    out["a_active"] = max(r for r, _ in act) if act else 0.0
    line = sorted((r, p) for r, p, _g, _s, on, _i in prof if on)
    if act:
        la = max((r for r, p in line if p > tol), default=0.0)
        outside = [r for r, p in line if p <= tol and r > 0 and r > la]
        first_inactive = min(outside) if outside else None
        out["a_line_last_active"] = la
        out["a_line_first_inactive"] = first_inactive
        if first_inactive is not None:
            out["a_bracket_mid"] = 0.5 * (la + first_inactive)
            out["a_bracket_rel_err"] = out["a_bracket_mid"] / a_h - 1.0
        inner = [(r, p) for r, p in act if r <= 0.8 * out["a_active"]] or act
        fit = fit_hertz([r for r, _ in inner], [p for _, p in inner])
        if fit:
            out["a_fit"], out["p0_fit"] = fit
            out["a_fit_rel_err"] = fit[0] / a_h - 1.0
            out["p0_fit_rel_err"] = fit[1] / p0_h - 1.0
        out["max_penetration"] = max(0.0, max(-g for _r, p, g, *_ in prof if p > tol))
    else:
        out["max_penetration"] = 0.0

    # Coulomb extras
    pair_force = [v for k, v in glo.items() if k.startswith("contact_force_") and k.endswith("_" + axis)]
    if pair_force:
        out["contact_force"] = abs(sum(pair_force))
        out["contact_force_vs_reaction_rel"] = (abs(sum(pair_force)) - load) / load if load else None
    active_glo = [v for k, v in glo.items() if k.startswith("contact_active_nodes_")]
    if active_glo:
        out["contact_active_nodes"] = int(round(sum(active_glo)))
    states = [s for _r, _p, _g, s, _o, _i in prof if s == s]
    if states:
        out["active_nodes_state"] = sum(1 for s in states if s > 0.5)
    out["min_pressure"] = min(p for _, p, *_ in prof)
    active_line = [p for r, p in line if p > tol]
    out["line_nonmonotone"] = sum(1 for a, b in zip(active_line, active_line[1:]) if b > a)
    out["profile_line"] = [[round(r, 6), round(p, 3)] for r, p in line if r <= 2.0 * a_h]
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("result")
    ap.add_argument("--case", required=True, choices=CASES)
    ap.add_argument("--step", type=int, help="time step (1-based; default the last)")
    ap.add_argument("--profile", action="store_true", help="keep profile_line in the JSON")
    a = ap.parse_args()
    out = analyze(a.case, read_result(a.result, a.step))
    if not a.profile:
        out.pop("profile_line", None)
    print(json.dumps({k: (float(f"{v:.6g}") if isinstance(v, float) else v) for k, v in out.items()}))


if __name__ == "__main__":
    sys.exit(main())
