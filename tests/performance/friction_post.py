#!/usr/bin/python3
"""Friction (sliding punch) post-processing of a Coulomb Exodus result.

  tests/performance/friction_post.py RESULT.e [--log stdout.txt] [--deck deck.xml] [--mu MU]

Prints one line of JSON with the keys of the CalculiX peer harness
(../shared/bench/calculix/ccxbench.py, analyze_friction; definitions in
../shared/bench/calculix/README.md, case friction) for xml/friction_punch.xml
or a copy of it (scripts/bench friction):

  history          one row per written (= converged) load step:
                   [step, t, Q, P, Q/P] with
                     Q = |reaction_top_x| * 2, P = -reaction_top_z * 2
                   (global variables: reactions of the node set `top`; x the
                   sliding direction, z the normal; the factor 2 = ccxbench
                   CASES["friction"]["sym_factor"]: the mesh is the half model
                   y >= 0, the keys are for the full model; P keeps ccxbench's
                   sign, positive in compression), and step / t in CalculiX's
                   convention: analysis step 1 (pressing) or 2 (sliding), t =
                   its total time, 0..1 in step 1 and 1..2 in step 2. Coulomb's
                   pseudo time T maps to it through the deck's functions
                   `press` (0..4) and `slide` (4..24):
                     step 1: t = T / 4,   step 2: t = 1 + (T - 4) / 20
  P_after_step1    P of the last step-1 row
  Q_end, P_end, Q_over_P_end, Q_over_muP_end   last step-2 row (Q_over_muP_end
                   is null when Q/P is 0, as in ccxbench)
  gross_slip_from_step_time, gross_slip_from_ux
                   first step-2 row with Q/P >= 0.99 mu: its step time t - 1,
                   and that times u_x = 0.01 (the top displacement at onset)
  Q_over_P_sliding_mean, Q_over_P_sliding_maxdev
                   mean of Q/P and max |Q/P - mu| over the step-2 rows with
                   Q/P >= 0.99 mu (null when there are none)
  active_slave_nodes_end      slave nodes with contact_pressure > 1e-9 (last step)
  slipping_slave_nodes_end    slave nodes with contact_state = 1 (last step): the
                   friction states are 0 inactive, 1 slip, 2 stick; in a
                   frictionless run state 1 means active (all active nodes
                   slide). null when the result has no contact_state.
  sticking_slave_nodes_end    slave nodes with contact_state = 2 (null for
                   frictionless states, see contact_states)
  max_nodal_tau_over_mu_p_end, slipping_slave_nodes_end_traction
                   ccxbench's own slip test on nodal tractions: tau = |tangential
                   part of the nodal multiplier| (contact_multiplier_* minus its
                   contact_normal_* component), p = contact_pressure; over the
                   active slave nodes, max tau / (mu p) and the count of nodes
                   with tau >= 0.99 mu p
  mu               the friction coefficient of the deck (Contact/Pairs/*/Friction
                   Coefficient), else --mu, else the benchmark's 0.3 (the keys
                   of a frictionless run are still evaluated with mu = 0.3)

Coulomb extras: frictionless (the deck has no Friction Law, or None), contact_states
("friction" when a pair has a friction law or a state 2 occurs, else
"frictionless"), contact_force_x_end / contact_force_z_end (pair force global
variables, full model) and contact_force_vs_reaction_rel_{x,z} (momentum
balance against the reactions), contact_active_nodes_end (global variable),
slave_nodes, nodes, elements, pseudo_time_end.
With --log (coulomb's console): per load step ("increment") newton_per_increment,
linear_per_increment, active_per_increment (the "contact 'NAME': N active nodes"
line; slip_per_increment / stick_per_increment when that line also counts
slip / stick nodes) and per_step (ccxbench: per analysis step, converged
increments and their Newton iterations).

Needs numpy and netCDF4: run with /usr/bin/python3 (Debian python3-netcdf4).
"""
import argparse
import json
import math
import os
import re
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import hertz_post  # noqa: E402  (read_result, _names: the Exodus reader of the Hertz cases)

# ccxbench.CASES["friction"]
MU = 0.3
UX = 0.01
DELTA = 0.002
SYM_FACTOR = 2.0
# the deck's load functions (xml/friction_punch.xml): press over [0, 4], slide over [4, 24]
SCHEDULE = {"press": (0.0, 4.0), "slide": (4.0, 24.0)}
FRICTION_KEYS = ("Friction Law", "Friction Coefficient")
NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
# the keys scripts/bench friction takes from analyze_files(), in this order:
# the ccxbench ones after the solver effort, the Coulomb extras after the
# timers (slip_/stick_per_increment only when the console has them)
BENCH_KEYS = ("mu", "history", "P_after_step1", "Q_end", "P_end", "Q_over_P_end", "Q_over_muP_end",
              "gross_slip_from_step_time", "gross_slip_from_ux", "Q_over_P_sliding_mean",
              "Q_over_P_sliding_maxdev", "active_slave_nodes_end", "slipping_slave_nodes_end",
              "sticking_slave_nodes_end", "max_nodal_tau_over_mu_p_end", "slipping_slave_nodes_end_traction",
              "contact_states", "slave_nodes")
BENCH_EXTRAS = ("contact_force_x_end", "contact_force_vs_reaction_rel_x", "contact_force_z_end",
                "contact_force_vs_reaction_rel_z", "contact_active_nodes_end", "active_per_increment",
                "slip_per_increment", "stick_per_increment", "linear_per_increment")


# ------------------------------------------------------------------ deck
def _sublist(node, name):
    return next((c for c in node.findall("ParameterList") if c.get("name") == name), None)


def read_deck(path):
    """{'schedule': {'press': (t0, t1), 'slide': (t0, t1)}, 'mu': float or None,
    'friction_law': str or None, 'formulation': str or None} from a Coulomb deck
    (the last contact pair's values; None = not given)"""
    out = {"schedule": dict(SCHEDULE), "mu": None, "friction_law": None, "formulation": None}
    if not path:
        return out
    root = ET.parse(path).getroot()
    functions = _sublist(root, "Functions")
    for name in SCHEDULE:
        f = _sublist(functions, name) if functions is not None else None
        if f is None:
            continue
        times = next((p.get("value") for p in f.findall("Parameter") if p.get("name") == "Times"), None)
        if times:
            values = [float(v) for v in times.strip("{} ").split(",")]
            out["schedule"][name] = (values[0], values[-1])
    contact = _sublist(root, "Contact")
    pairs = _sublist(contact, "Pairs") if contact is not None else None
    for pair in (pairs.findall("ParameterList") if pairs is not None else []):
        for p in pair.findall("Parameter"):
            if p.get("name") == "Friction Coefficient":
                out["mu"] = float(p.get("value"))
            elif p.get("name") == "Friction Law":
                out["friction_law"] = p.get("value")
            elif p.get("name") == "Formulation":
                out["formulation"] = p.get("value")
    return out


def analysis_step(T, schedule=None):
    """Coulomb pseudo time T -> (CalculiX analysis step, its total time)"""
    s = schedule or SCHEDULE
    p0, p1 = s["press"]
    s0, s1 = s["slide"]
    if T <= p1 + 1e-9 * max(1.0, abs(p1)):
        return 1, (T - p0) / (p1 - p0)
    return 2, 1.0 + (T - s0) / (s1 - s0)


def pseudo_time(step, t, schedule=None):
    """inverse of analysis_step"""
    s = schedule or SCHEDULE
    p0, p1 = s["press"]
    s0, s1 = s["slide"]
    return p0 + t * (p1 - p0) if step == 1 else s0 + (t - 1.0) * (s1 - s0)


# ------------------------------------------------------------------ Exodus
def read_history(path):
    """{'times': [...], 'glo': {name: [value per time step]}, 'states': [set of
    contact_state values per step] or None, 'last': hertz_post.read_result(path)}"""
    import numpy as np
    from netCDF4 import Dataset
    with Dataset(path) as ds:
        ds.set_auto_mask(False)
        times = [float(t) for t in ds.variables["time_whole"][:]] if "time_whole" in ds.variables else []
        if not times:
            raise RuntimeError(f"{path}: no time step written")
        glo = {}
        names = hertz_post._names(ds, "name_glo_var")
        if names:
            vals = np.array(ds.variables["vals_glo_var"][:], dtype=float).reshape(len(times), -1)
            glo = {name: [float(v) for v in vals[:, j]] for j, name in enumerate(names)}
        states = None
        nod_names = hertz_post._names(ds, "name_nod_var")
        if "contact_state" in nod_names:
            var = ds.variables[f"vals_nod_var{nod_names.index('contact_state') + 1}"]
            states = [set(np.unique(np.rint(var[k]).astype(int)).tolist()) for k in range(len(times))]
    return {"times": times, "glo": glo, "states": states, "last": hertz_post.read_result(path)}


# ------------------------------------------------------------------ analysis
def analyze(hist, mu=MU, schedule=None, frictional=None, ux=UX, sym_factor=SYM_FACTOR):
    """the ccxbench.analyze_friction keys (+ Coulomb extras) of read_history()"""
    glo = hist["glo"]
    for key in ("reaction_top_x", "reaction_top_z"):
        if key not in glo:
            raise RuntimeError(f"result has no global variable '{key}'")
    res = hist["last"]
    out = {"mu": mu, "nodes": res["nodes"], "elements": res["elements"],
           "slave_nodes": len(res["sets"].get("slave", ())), "pseudo_time_end": hist["times"][-1]}
    rows = []
    for T, fx, fz in zip(hist["times"], glo["reaction_top_x"], glo["reaction_top_z"]):
        # ccxbench: tangential (x) and normal (z) reaction of the driven top
        # face, positive magnitudes, full (mirrored) model
        step, t = analysis_step(T, schedule)
        Q, P = abs(fx) * sym_factor, -fz * sym_factor
        rows.append({"step": step, "t": t, "Q": Q, "P": P, "Q_over_P": (Q / P if P else None)})
    out["history"] = [[r["step"], round(r["t"], 5), round(r["Q"], 3), round(r["P"], 3),
                       round(r["Q_over_P"], 5) if r["Q_over_P"] is not None else None] for r in rows]
    s1 = [r for r in rows if r["step"] == 1]
    s2 = [r for r in rows if r["step"] == 2]
    out["P_after_step1"] = s1[-1]["P"] if s1 else None
    for key in ("Q_end", "P_end", "Q_over_P_end", "Q_over_muP_end", "gross_slip_from_step_time",
                "gross_slip_from_ux", "Q_over_P_sliding_mean", "Q_over_P_sliding_maxdev"):
        out[key] = None
    if s2:
        last = s2[-1]
        out["Q_end"], out["P_end"] = last["Q"], last["P"]
        out["Q_over_P_end"] = last["Q_over_P"]
        out["Q_over_muP_end"] = last["Q_over_P"] / mu if last["Q_over_P"] else None
        onset = [r["t"] - 1.0 for r in s2 if r["Q_over_P"] and r["Q_over_P"] >= 0.99 * mu]
        out["gross_slip_from_step_time"] = onset[0] if onset else None
        out["gross_slip_from_ux"] = onset[0] * ux if onset else None
        sliding = [r["Q_over_P"] for r in s2 if r["Q_over_P"] and r["Q_over_P"] >= 0.99 * mu]
        if sliding:
            out["Q_over_P_sliding_mean"] = sum(sliding) / len(sliding)
            out["Q_over_P_sliding_maxdev"] = max(abs(x - mu) for x in sliding)

    # nodal values of the last step
    nod = res["nod"]
    slave = list(res["sets"].get("slave", ()))
    p = nod.get("contact_pressure")
    state = nod.get("contact_state")
    seen_stick = any(2 in s for s in hist["states"]) if hist["states"] else False
    friction_states = bool(frictional) or seen_stick
    out["contact_states"] = ("friction" if friction_states else "frictionless") if state is not None else None
    out["active_slave_nodes_end"] = sum(1 for i in slave if p[i] > 1e-9) if p is not None else None
    if state is not None:
        out["slipping_slave_nodes_end"] = sum(1 for i in slave if int(round(float(state[i]))) == 1)
        out["sticking_slave_nodes_end"] = (sum(1 for i in slave if int(round(float(state[i]))) == 2)
                                           if friction_states else None)
    else:
        out["slipping_slave_nodes_end"] = out["sticking_slave_nodes_end"] = None
    lam = [nod.get("contact_multiplier_" + c) for c in "xyz"]
    nrm = [nod.get("contact_normal_" + c) for c in "xyz"]
    out["max_nodal_tau_over_mu_p_end"] = out["slipping_slave_nodes_end_traction"] = None
    if p is not None and all(v is not None for v in lam + nrm):
        ratio_max, n_slip = 0.0, 0
        for i in slave:
            if p[i] <= 1e-9:
                continue
            lv = [v[i] for v in lam]
            nv = [v[i] for v in nrm]
            ln = sum(a * b for a, b in zip(lv, nv))
            tau = math.sqrt(sum((a - ln * b) ** 2 for a, b in zip(lv, nv)))
            ratio_max = max(ratio_max, tau / (mu * p[i]))
            n_slip += 1 if tau >= 0.99 * mu * p[i] else 0
        ratio_max = float(ratio_max)
        out["max_nodal_tau_over_mu_p_end"] = ratio_max
        out["slipping_slave_nodes_end_traction"] = n_slip

    # Coulomb extras: pair force against the reaction of `top` (full model)
    g_end = {k: v[-1] for k, v in glo.items()}
    for c in ("x", "z"):
        force = [v for k, v in g_end.items() if k.startswith("contact_force_") and k.endswith("_" + c)]
        if force:
            total = abs(sum(force)) * sym_factor
            reaction = abs(g_end[f"reaction_top_{c}"]) * sym_factor
            out[f"contact_force_{c}_end"] = total
            out[f"contact_force_vs_reaction_rel_{c}"] = (total - reaction) / reaction if reaction > 1e-9 else None
    active = [v for k, v in g_end.items() if k.startswith("contact_active_nodes_")]
    out["contact_active_nodes_end"] = int(round(sum(active))) if active else None
    return out


# ------------------------------------------------------------------ console
ITER_ROW = re.compile(r"^\s+(\d+)\s+(" + NUM + r")\s+(\S+)\s+(\d+)\s+(" + NUM + r")(?:\s|$)")
STEP_LINE = re.compile(r"step \d+ converged: t = (" + NUM + r"), (\d+) Newton / (\d+) linear")
PAIR_LINE = re.compile(r"^\s+contact '([^']*)': (\d+) active nodes(.*)$")


def console_keys(text, schedule=None):
    """per load step (= CalculiX increment) figures from coulomb's console; the
    iteration rows are matched on their first five columns only (iter,
    |residual|, |increment|, lin.it, time[s]) so that new contact columns do
    not hide them"""
    out = {"iteration_seconds": [], "iteration_linear": [], "newton_per_increment": [],
           "linear_per_increment": [], "increment_times": [], "active_per_increment": []}
    pairs = []  # per converged load step: the "contact 'NAME': ..." lines after it
    for line in text.splitlines():
        row = ITER_ROW.match(line)
        if row and int(row.group(1)) >= 1:
            out["iteration_seconds"].append(float(row.group(5)))
            out["iteration_linear"].append(int(row.group(4)))
            continue
        m = STEP_LINE.search(line)
        if m:
            out["increment_times"].append(float(m.group(1)))
            out["newton_per_increment"].append(int(m.group(2)))
            out["linear_per_increment"].append(int(m.group(3)))
            pairs.append([])
            continue
        m = PAIR_LINE.match(line)
        if m and pairs:
            pairs[-1].append(m)
    out["active_per_increment"] = [sum(int(m.group(2)) for m in ms) if ms else None for ms in pairs]
    for word in ("slip", "stick"):
        # a pair line that also counts slip / stick nodes ("..., 12 slip, 3 stick, ...")
        counts = [[re.search(r"(\d+) " + word, m.group(3)) for m in ms] for ms in pairs]
        values = [sum(int(c.group(1)) for c in cs) if cs and all(cs) else None for cs in counts]
        if any(v is not None for v in values):
            out[word + "_per_increment"] = values
    per = {}
    for T, n in zip(out["increment_times"], out["newton_per_increment"]):
        step = analysis_step(T, schedule)[0]
        d = per.setdefault(step, {"step": step, "increments": 0, "iterations": 0})
        d["increments"] += 1
        d["iterations"] += n
    out["per_step"] = [per[k] for k in sorted(per)]
    return out


def analyze_files(result, log=None, deck=None, mu=None, ux=UX, sym_factor=SYM_FACTOR):
    """everything above for one run: the Exodus keys, plus the console keys with
    a log (ux, sym_factor: see analyze; ironing_post.py passes its own)"""
    info = read_deck(deck)
    mu = info["mu"] if info["mu"] is not None else (mu if mu is not None else MU)
    frictional = info["friction_law"] not in (None, "None")
    out = analyze(read_history(result), mu, info["schedule"], frictional=frictional, ux=ux,
                  sym_factor=sym_factor)
    out["frictionless"] = (not frictional) if deck else None
    out["formulation"] = info["formulation"]
    if log:
        text = open(log, errors="replace").read()
        out.update({k: v for k, v in console_keys(text, info["schedule"]).items()
                    if k not in ("iteration_seconds", "iteration_linear", "increment_times")})
    return out


def print_keys(out):
    """One JSON line, floats to 6 significant digits."""
    def rounded(v):
        if isinstance(v, float):
            return float(f"{v:.6g}")
        if isinstance(v, list):
            return [rounded(x) for x in v]
        return v
    print(json.dumps({k: rounded(v) for k, v in out.items()}))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("result")
    ap.add_argument("--log", help="coulomb's console output (stdout.txt of scripts/bench)")
    ap.add_argument("--deck", help="the deck that was run (load functions, friction coefficient)")
    ap.add_argument("--mu", type=float, help=f"friction coefficient when the deck has none (default {MU})")
    a = ap.parse_args()
    print_keys(analyze_files(a.result, a.log, a.deck, a.mu))
    return 0


if __name__ == "__main__":
    sys.exit(main())
