#!/usr/bin/python3
"""Plot the contact pressure of a Coulomb Hertz result against Hertz theory.

  tests/performance/plot_pressure.py RESULT.e OUT.png --case hertz2d|hertz3d [--step K]

Dots: contact_pressure of every slave node (last time step, or step K)
against r (2D: |x|, 3D: sqrt(x^2 + y^2)); the nodes on the +x line
(hertz_post.py) are joined by a line. Curve: Hertz p0 sqrt(1 - r^2/a^2)
for the measured reaction of `top` (hertz_post.hertz). The title gives
P (or P'), p_max and a_fit against p0 and a of the Hertz solution.

Needs numpy, netCDF4 and matplotlib (Agg backend): /usr/bin/python3 with
Debian python3-netcdf4 and python3-matplotlib.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True  # no __pycache__ in the source tree
import hertz_post  # noqa: E402


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("result")
    ap.add_argument("png")
    ap.add_argument("--case", required=True, choices=hertz_post.CASES)
    ap.add_argument("--step", type=int, help="time step (1-based; default the last)")
    a = ap.parse_args()

    res = hertz_post.read_result(a.result, a.step)
    out = hertz_post.analyze(a.case, res)
    prof = hertz_post.slave_profile(a.case, res)
    a_h, p0_h = out["a_hertz"], out["p0_hertz"]
    rmax = 2.0 * a_h

    fig, ax = plt.subplots(figsize=(7.5, 4.8))
    r_all = np.array([r for r, *_ in prof])
    p_all = np.array([p for _, p, *_ in prof])
    keep = r_all <= rmax
    ax.plot(r_all[keep], p_all[keep], "o", ms=3.5, color="tab:blue", alpha=0.45, label="slave nodes")
    line = sorted((r, p) for r, p, _g, _s, on, _i in prof if on and r <= rmax)
    if line:
        ax.plot([r for r, _ in line], [p for _, p in line], "-o", ms=4, color="tab:blue",
                label="slave nodes on the +x line")
    r = np.linspace(0.0, a_h, 400)
    ax.plot(r, p0_h * np.sqrt(np.clip(1.0 - (r / a_h) ** 2, 0.0, None)), "k-", lw=1.5,
            label=f"Hertz: p0 = {p0_h:.0f} MPa, a = {a_h:.3f} mm")
    if out.get("a_fit"):
        rf = np.linspace(0.0, out["a_fit"], 200)
        ax.plot(rf, out["p0_fit"] * np.sqrt(np.clip(1.0 - (rf / out["a_fit"]) ** 2, 0.0, None)), "--",
                color="tab:orange", lw=1.2,
                label=f"fit: p0 = {out['p0_fit']:.0f} MPa, a = {out['a_fit']:.3f} mm")
    load = (f"P = {out['P']:.0f} N" if a.case == "hertz3d" else f"P' = {out['P_per_length']:.0f} N/mm")
    ax.set_title(f"{a.case} {os.path.basename(os.path.dirname(os.path.abspath(a.result)))}: {load}, "
                 f"{out['nodes']} nodes\np_max = {out['p_max']:.0f} MPa "
                 f"({100 * out['p_max_rel_err']:+.1f} % vs p0), active slave nodes {out['active_slave_nodes']}",
                 fontsize=10)
    ax.set_xlabel("r = |x| [mm]" if a.case == "hertz2d" else "r = sqrt(x² + y²) [mm]")
    ax.set_ylabel("contact pressure [MPa]")
    ax.set_xlim(0.0, rmax)
    ax.set_ylim(bottom=min(0.0, float(p_all[keep].min()) * 1.1 if keep.any() else 0.0))
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(a.png, dpi=110)
    return 0


if __name__ == "__main__":
    sys.exit(main())
