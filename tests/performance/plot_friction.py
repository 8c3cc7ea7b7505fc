#!/usr/bin/python3
"""Plot Q/P of a Coulomb sliding-punch result against pseudo time.

  tests/performance/plot_friction.py RESULT.e OUT.png [--deck deck.xml] [--mu MU]
                                     [--calculix CCX.json] [--case friction|ironing]

Q/P of every written load step (friction_post.py: Q = |reaction_top_x|,
P = -reaction_top_z, both x 2 for the full model) against Coulomb's pseudo
time (0..4 pressing, 4..24 sliding with xml/friction_punch.xml); the
friction coefficient mu as a dashed line, the end of pressing as a dotted
one. A second axis gives P. --calculix adds the history of a CalculiX run
(the JSON line of ../shared/bench/calculix/run_case.sh, or the calculix
object of a scripts/bench result.json) mapped onto the same pseudo time.
scripts/bench friction writes it as friction_qp.png in the run directory.
--case ironing: the ironing sphere (tests/performance/ironing_hertz3d.xml,
full model: Q and P without the factor 2; 0..3 pressing, 3..15 sliding);
scripts/bench ironing writes it as ironing_qp.png.

Needs numpy, netCDF4 and matplotlib (Agg backend): /usr/bin/python3 with
Debian python3-netcdf4 and python3-matplotlib.
"""
import argparse
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import friction_post  # noqa: E402

# case: (factor of Q and P, x axis label)
CASES = {"friction": (friction_post.SYM_FACTOR, "pseudo time (0..4: press u_z = -0.002, 4..24: slide u_x = 0.01)"),
         "ironing": (1.0, "pseudo time (0..3: press u_z = -0.05, 3..15: slide u_x = 0.3)")}


def load_calculix(path):
    """history of a CalculiX JSON (a run_case.sh line, or a result.json with 'calculix')"""
    with open(path) as f:
        text = f.read().strip()
    try:
        obj = json.loads(text)
    except ValueError:  # a file of JSON lines: the last object
        obj = json.loads(text.splitlines()[-1])
    if "calculix" in obj and isinstance(obj["calculix"], dict):
        obj = obj["calculix"]
    return obj.get("history") or [], obj


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("result")
    ap.add_argument("png")
    ap.add_argument("--deck", help="the deck that was run (load functions, friction coefficient)")
    ap.add_argument("--mu", type=float, help=f"friction coefficient when the deck has none (default {friction_post.MU})")
    ap.add_argument("--calculix", help="CalculiX JSON to overlay (its history)")
    ap.add_argument("--case", choices=sorted(CASES), default="friction",
                    help="friction (sliding punch, half model; default) or ironing (sphere, full model)")
    a = ap.parse_args()

    info = friction_post.read_deck(a.deck)
    schedule = info["schedule"]
    sym_factor, xlabel = CASES[a.case]
    ux = friction_post.UX
    if a.case == "ironing":
        import ironing_post  # the slide of `top` from the deck
        ux = ironing_post.slide_ux(a.deck)
    mu = info["mu"] if info["mu"] is not None else (a.mu if a.mu is not None else friction_post.MU)
    out = friction_post.analyze(friction_post.read_history(a.result), mu, schedule,
                                frictional=info["friction_law"] not in (None, "None"), sym_factor=sym_factor, ux=ux)
    hist = out["history"]
    T = [friction_post.pseudo_time(s, t, schedule) for s, t, *_ in hist]
    qp = [r[4] if r[4] is not None else float("nan") for r in hist]
    P = [r[3] for r in hist]

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    label = "Coulomb" + (" (frictionless deck)" if a.deck and info["friction_law"] in (None, "None") else "")
    ax.plot([0.0] + T, [0.0] + qp, "-o", ms=4, color="tab:blue", label=f"{label}: Q/P")
    ccx_note = ""
    if a.calculix:
        ccx_hist, ccx = load_calculix(a.calculix)
        if ccx_hist:
            Tc = [friction_post.pseudo_time(s, t, schedule) for s, t, *_ in ccx_hist]
            ax.plot([0.0] + Tc, [0.0] + [r[4] if r[4] is not None else float("nan") for r in ccx_hist], "-s",
                    ms=3.5, color="tab:orange", alpha=0.8,
                    label=f"CalculiX {ccx.get('contact', '')} mu = {ccx.get('mu', '?')}: Q/P")
            ccx_note = f", CalculiX Q/P end {ccx.get('Q_over_P_end', float('nan')):.4f}"
    t_press = schedule["press"][1]
    ax.axhline(mu, ls="--", color="k", lw=1.2, label=f"mu = {mu:g}")
    ax.axvline(t_press, ls=":", color="grey", lw=1.0)
    ax.text(t_press, 0.02, " sliding starts", color="grey", fontsize=8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("Q / P (full model)")
    ax.set_xlim(0.0, max(T + [schedule["slide"][1]]))
    ax.set_ylim(0.0, max(1.25 * mu, 1.1 * max([q for q in qp if q == q] or [0.0])))
    ax.grid(alpha=0.3)
    ax2 = ax.twinx()
    ax2.plot([0.0] + T, [0.0] + P, ":", color="tab:green", lw=1.2)
    ax2.set_ylabel("Coulomb P [N] (dotted)", color="tab:green")
    ax2.set_ylim(bottom=0.0)
    end = out.get("Q_over_P_end")
    slip = out.get("gross_slip_from_ux")
    ax.set_title(f"{a.case} {os.path.basename(os.path.dirname(os.path.abspath(a.result)))}: "
                 f"{out['nodes']} nodes, P_end = {out.get('P_end') or float('nan'):.1f} N\n"
                 f"Q/P end {end if end is not None else float('nan'):.4f}, gross slip from u_x = "
                 f"{f'{slip:.4g}' if slip is not None else '-'}{ccx_note}", fontsize=10)
    ax.legend(fontsize=8, loc="center right")
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
