#!/usr/bin/python3
"""Check of tests/zoo/sliding_cylinder_2d.xml: a stiff cylinder (half disc) pressed
into a softer slab, then dragged in gross slip over four contact widths, mu = 0.3,
plane strain.

    /usr/bin/python3 tests/zoo/sliding_cylinder_2d_check.py RESULT.e

Checked (the deck's leading comment gives the derivations and tolerances):
  value:      mean of Q/P over the last half of the slide (pseudo time in
              (24, 44], 20 increments), Q = |reaction_top_x|, P = -reaction_top_y
              (per unit thickness), against Coulomb's mu = 0.3 corrected for the
              tilt tau of the resultant normal force (unlike materials: the
              pressure centroid lies (8/3) gamma a behind the die's lowest
              point, tan(pi gamma) = |beta| mu):
              (mu - tau) / (1 + mu tau), tau = (8/3) gamma a / R, a the Hertz
              half-width at the window's mean P; 1 % relative
  condition:  the slide reached its end (t = 44);
              P constant over that window (max |P / mean P - 1| <= 3 %);
              Hertz line contact, p_max = 2 P / (pi a), a = sqrt(4 P R / (pi E*)),
              at the measured P against the peak p0_fit of the Hertz profile
              fitted to the nodal contact pressures of the slave (slab) nodes
              (least squares of p^2 = c0 + c1 x + c2 x^2, i.e.
              p0^2 (1 - (x - xc)^2 / a^2) with a free centre xc, over the
              active nodes within 0.8 of the patch's half-width of its centre):
              after pressing (the last step with t <= 4) within 10 % (3 % mesh + |beta| mu = 7 %, the
              first-order coupling of the stick-zone friction with the normal
              problem for unlike materials) and at the end of the slide
              (gross slip, the coupling of second order) within 3 %.
Extras: the Q/P and P histories, nodal p_max, a_fit, active / stick nodes.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "sliding_cylinder_2d"
MU = 0.3
R = 10.0
E_DIE, E_SLAB, NU = 2.1e5, 2.1e4, 0.3
E_STAR = 1.0 / ((1 - NU ** 2) / E_DIE + (1 - NU ** 2) / E_SLAB)
G_DIE, G_SLAB = E_DIE / (2 * (1 + NU)), E_SLAB / (2 * (1 + NU))
BETA = ((1 - 2 * NU) / G_DIE - (1 - 2 * NU) / G_SLAB) / (2 * ((1 - NU) / G_DIE + (1 - NU) / G_SLAB))
GAMMA = math.atan(abs(BETA) * MU) / math.pi
T_PRESS, T_END = 4.0, 44.0   # pressing over [0, 4], sliding over [4, 44]
TOL_MU, TOL_P = 0.01, 0.03
TOL_HERTZ_SLIP, TOL_HERTZ_PRESS = 0.03, 0.10
EPS = 1e-6


def hertz(P):
    """(a, p_max) of Hertz line contact at the load P per unit thickness"""
    a = math.sqrt(4.0 * P * R / (math.pi * E_STAR))
    return a, 2.0 * P / (math.pi * a)


def lstsq(rows, rhs):
    """least squares by the normal equations (a handful of unknowns)"""
    import numpy as np
    A = np.array(rows, dtype=float)
    return np.linalg.solve(A.T @ A, A.T @ np.array(rhs, dtype=float))


def fit_profile(xs, ps):
    """p^2 = p0^2 (1 - (x - xc)^2 / a^2) fitted to the active nodes within 0.8 of
    the half-width of the patch centre -> dict(p0, a, xc, nodes) or None"""
    act = [(x, p) for x, p in zip(xs, ps) if p > 1e-6 * max(ps)]
    if len(act) < 4:
        return None
    lo, hi = min(x for x, _ in act), max(x for x, _ in act)
    xc0, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    use = [(x, p) for x, p in act if abs(x - xc0) <= 0.8 * half] or act
    c0, c1, c2 = lstsq([[1.0, x, x * x] for x, _ in use], [p * p for _, p in use])
    if c2 >= 0:
        return None
    xc = -c1 / (2 * c2)
    p02 = c0 - c1 * c1 / (4 * c2)
    if p02 <= 0:
        return None
    return {"p0": math.sqrt(p02), "a": math.sqrt(-p02 / c2), "xc": xc, "nodes": len(use), "active": len(act)}


r = zx.open_result(CASE, sys.argv)
try:
    rx = r.glob("reaction_top_x")
    ry = r.glob("reaction_top_y")
    # (a frictionless variant of the deck has no stick count)
    stick = r.glob("contact_stick_nodes_die") if "contact_stick_nodes_die" in r.global_names else [0] * r.steps
    slave = r.node_set("slave")
    r.nodal("contact_pressure")
except KeyError as e:
    zx.fail_read(CASE, str(e))
times = [float(t) for t in r.times]
Q = [abs(v) for v in rx]
P = [-v for v in ry]
qp = [q / p if p > 0 else float("nan") for q, p in zip(Q, P)]
window = [k for k, t in enumerate(times) if t > 0.5 * (T_PRESS + T_END) + EPS]
problems = []
if times[-1] < T_END - EPS:
    problems.append(f"the run ended at t = {times[-1]:g} < {T_END:g}")
mean_qp = sum(qp[k] for k in window) / len(window) if window else -1.0

p_dev = None
mu_eff, tau = MU, None
if window:
    p_mean = sum(P[k] for k in window) / len(window)
    tau = (8.0 / 3.0) * GAMMA * hertz(p_mean)[0] / R
    mu_eff = (MU - tau) / (1 + MU * tau)
    p_dev = max(abs(P[k] / p_mean - 1.0) for k in window)
    if not p_dev <= TOL_P:
        problems.append(f"P varies by {p_dev:.2%} > {TOL_P:.0%} in gross slip")


def hertz_at(k, tol, label):
    """Hertz keys of step k (0-based); appends to problems when beyond tol"""
    a_h, p0_h = hertz(P[k])
    p = r.nodal("contact_pressure", step=k + 1)
    xs = [float(r.coords[i, 0]) for i in slave]
    ps = [float(p[i]) for i in slave]
    fit = fit_profile(xs, ps)
    out = {f"{label}_t": times[k], f"{label}_P": P[k], f"{label}_a_hertz": a_h, f"{label}_p0_hertz": p0_h,
           f"{label}_p_max_nodal_rel_err": max(ps) / p0_h - 1.0}
    if fit is None:
        problems.append(f"{label}: no Hertz fit of the contact pressure")
        return out
    err = fit["p0"] / p0_h - 1.0
    out.update({f"{label}_p0_fit": fit["p0"], f"{label}_p0_fit_rel_err": err,
                f"{label}_a_fit_rel_err": fit["a"] / a_h - 1.0, f"{label}_patch_centre": fit["xc"],
                f"{label}_active_nodes": fit["active"]})
    if not abs(err) <= tol:
        problems.append(f"{label}: p0_fit {fit['p0']:.1f} vs Hertz {p0_h:.1f} ({err:+.2%}) beyond {tol:.0%}")
    return out


extra = {}
# the last pressing step: t = 4, or the last t < 4 when a cutback moved the steps
kp = max((k for k, t in enumerate(times) if t <= T_PRESS + EPS), default=None)
if kp is None:
    problems.append(f"no pressing step (t <= {T_PRESS:g})")
else:
    extra.update(hertz_at(kp, TOL_HERTZ_PRESS, "press"))
if window:
    extra.update(hertz_at(len(times) - 1, TOL_HERTZ_SLIP, "slide_end"))

summary = (f"slide complete; P constant within {TOL_P:.0%}; p0 of the fitted Hertz profile within "
           f"{TOL_HERTZ_PRESS:.0%} of Hertz after pressing and {TOL_HERTZ_SLIP:.0%} at the end of the slide")
zx.report(CASE, "mean Q/P over the last half of the slide (t in (24, 44])", mean_qp, mu_eff, TOL_MU,
          condition=(not problems, "; ".join(problems) or summary),
          mu=MU, beta=BETA, gamma=GAMMA, tau=tau, steps_written=r.steps, time=times[-1], window_steps=len(window),
          Q_over_P_window_min=min((qp[k] for k in window), default=None),
          Q_over_P_window_max=max((qp[k] for k in window), default=None),
          P_window_max_rel_dev=p_dev, stick_nodes_window_max=max((int(stick[k]) for k in window), default=None),
          **extra,
          history=[[round(t, 3), round(q, 5), round(pp, 2)] for t, q, pp in zip(times, qp, P)])
