#!/usr/bin/python3
"""Ironing (sliding sphere) post-processing of a Coulomb Exodus result.

  tests/performance/ironing_post.py RESULT.e [--log stdout.txt] [--deck deck.xml]
      (--deck default: tests/performance/ironing_hertz3d.xml)

Prints one line of JSON for tests/performance/ironing_hertz3d.xml or a copy
of it (scripts/bench ironing): the sphere of the Hertz 3D mesh pressed
(function `press`, pseudo time 0..3) and dragged along +x (function `slide`,
3..15), Coulomb friction. The keys are those of friction_post.py, same
names and definitions, with two differences:

  history          [step, t, Q, P, Q/P] per written (= converged) load step,
                   Q = |reaction_top_x|, P = -reaction_top_z: the mesh is the
                   full model, no factor; step 1 = pressing, 2 = sliding and
                   t = 0..1 while pressing, 1..2 while sliding (friction_post's
                   convention, the schedule read from the deck's functions
                   press and slide: t - 1 is the fraction of the slide done)
  gross_slip_from_ux  onset step time x the slide of `top` (the deck's
                   Dirichlet condition on `top`, component x: 0.3 mm)

Extras of the ironing case:
  patch_x_per_increment   per written step, the centre of the contact patch
                   along x in the current configuration: mean of X + u_x over
                   the slave nodes with contact_pressure > 1e-9, weighted by
                   the pressure
  patch_x_after_press, patch_x_end, patch_shift (= end - after press)
  top_ux_end, patch_shift_over_top_ux   u_x of the node set `top` at the
                   end (the imposed slide) and patch_shift / top_ux_end: about
                   1 when the patch moves with the sphere (less by the shear
                   of the indenter and the block under Q)
  stick_per_increment, slip_per_increment   per written step, from the
                   global variables contact_stick_nodes_<pair> and
                   contact_active_nodes_<pair> (slip = active - stick)

Needs numpy and netCDF4: run with /usr/bin/python3 (Debian python3-netcdf4).
"""
import argparse
import os
import sys
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import friction_post  # noqa: E402
import hertz_post  # noqa: E402

UX = 0.3  # the slide of `top` in tests/performance/ironing_hertz3d.xml
DECK = os.path.join(os.path.dirname(os.path.abspath(__file__)), "ironing_hertz3d.xml")
SYM_FACTOR = 1.0  # full model
# the keys scripts/bench ironing takes from analyze_files(): after the solver
# effort, and after the per-case keys (the Coulomb extras)
BENCH_KEYS = ("history", "Q_over_P_end", "mu", "P_after_step1", "Q_end", "P_end", "Q_over_muP_end",
              "gross_slip_from_step_time", "gross_slip_from_ux", "Q_over_P_sliding_mean",
              "Q_over_P_sliding_maxdev", "active_slave_nodes_end", "slipping_slave_nodes_end",
              "sticking_slave_nodes_end", "max_nodal_tau_over_mu_p_end", "slipping_slave_nodes_end_traction",
              "contact_states", "slave_nodes", "patch_x_after_press", "patch_x_end", "patch_shift", "top_ux_end",
              "patch_shift_over_top_ux")
BENCH_EXTRAS = ("contact_force_x_end", "contact_force_vs_reaction_rel_x", "contact_force_z_end",
                "contact_force_vs_reaction_rel_z", "contact_active_nodes_end", "active_per_increment",
                "stick_per_increment", "slip_per_increment", "linear_per_increment", "patch_x_per_increment")


def slide_ux(deck):
    """Value of the deck's Dirichlet condition on `top`, component x (default UX)"""
    if not deck:
        return UX
    root = ET.parse(deck).getroot()
    for bc in root.findall("./ParameterList[@name='Dirichlet Conditions']/ParameterList"):
        p = {q.get("name"): q.get("value") for q in bc.findall("Parameter")}
        if p.get("Node Set") == "top" and p.get("Component") == "x" and p.get("Value") is not None:
            return float(p["Value"])
    return UX


def patch_track(path):
    """per written step: pressure-weighted mean current x of the active slave
    nodes (None without active nodes), and the mean u_x of `top`"""
    import numpy as np
    from netCDF4 import Dataset
    with Dataset(path) as ds:
        ds.set_auto_mask(False)
        nt = len(ds.variables["time_whole"][:])
        X = np.array(ds.variables["coordx"][:], dtype=float)
        sets = {name: np.array(ds.variables[f"node_ns{j + 1}"][:], dtype=int) - 1
                for j, name in enumerate(hertz_post._names(ds, "ns_names"))
                if f"node_ns{j + 1}" in ds.variables}
        names = hertz_post._names(ds, "name_nod_var")
        if "contact_pressure" not in names or "displacement_x" not in names or "slave" not in sets:
            return None, None
        p_all = ds.variables[f"vals_nod_var{names.index('contact_pressure') + 1}"]
        u_all = ds.variables[f"vals_nod_var{names.index('displacement_x') + 1}"]
        slave, top = sets["slave"], sets.get("top")
        patch, top_ux = [], []
        for k in range(nt):
            p = np.array(p_all[k], dtype=float)[slave]
            u = np.array(u_all[k], dtype=float)
            active = p > 1e-9
            patch.append(float(np.sum(p[active] * (X[slave][active] + u[slave][active])) / np.sum(p[active]))
                         if active.any() else None)
            top_ux.append(float(np.mean(u[top])) if top is not None and len(top) else None)
    return patch, top_ux


def analyze_files(result, log=None, deck=DECK):
    """friction_post.analyze_files on the full model, plus the ironing extras
    (deck: the one that was run; default the repository deck)"""
    info = friction_post.read_deck(deck)
    out = friction_post.analyze_files(result, log, deck, ux=slide_ux(deck), sym_factor=SYM_FACTOR)
    hist = friction_post.read_history(result)
    glo = hist["glo"]
    stick = [v for k, v in glo.items() if k.startswith("contact_stick_nodes_")]
    active = [v for k, v in glo.items() if k.startswith("contact_active_nodes_")]
    if stick and active:
        st = [int(round(sum(vals))) for vals in zip(*stick)]
        ac = [int(round(sum(vals))) for vals in zip(*active)]
        out["stick_per_increment"] = st
        out["slip_per_increment"] = [a - s for a, s in zip(ac, st)]
    patch, top_ux = patch_track(result)
    if patch is None:
        return out
    press_end = info["schedule"]["press"][1]
    after_press = [x for T, x in zip(hist["times"], patch) if T <= press_end + 1e-9 * max(1.0, press_end)]
    out["patch_x_per_increment"] = patch
    out["patch_x_after_press"] = after_press[-1] if after_press else None
    out["patch_x_end"] = patch[-1]
    out["top_ux_end"] = top_ux[-1]
    shift = (patch[-1] - out["patch_x_after_press"]
             if patch[-1] is not None and out["patch_x_after_press"] is not None else None)
    out["patch_shift"] = shift
    out["patch_shift_over_top_ux"] = shift / top_ux[-1] if shift is not None and top_ux[-1] else None
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("result")
    ap.add_argument("--log", help="coulomb's console output (stdout.txt of scripts/bench)")
    ap.add_argument("--deck", default=DECK, help="the deck that was run (load functions, friction coefficient, "
                                                 "slide; default tests/performance/ironing_hertz3d.xml)")
    a = ap.parse_args()
    friction_post.print_keys(analyze_files(a.result, a.log, a.deck))
    return 0


if __name__ == "__main__":
    sys.exit(main())
