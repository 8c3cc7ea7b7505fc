#!/usr/bin/python3
"""Check of tests/zoo/stacked_blocks_2d.xml: three stacked blocks, the top one dragged.

    /usr/bin/python3 tests/zoo/stacked_blocks_2d_check.py RESULT.e

Q / P at the last step (Q = reaction_top_x, P = -reaction_top_y) against the
lower interface's mu = 0.2, 2e-3 relative (the deck's comment says why).
Extras: each interface's active / slipping / sticking slave nodes, the largest
normal tilt |n_x| over the active nodes of both interfaces, and the mean slip
of the upper interface relative to the lower one's (the middle block should
move with the top block: small).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "stacked_blocks_2d"
MU_LOWER = 0.2
TOLERANCE = 2e-3

r = zx.open_result(CASE, sys.argv)
try:
    Q = r.glob_last("reaction_top_x")
    P = -r.glob_last("reaction_top_y")
    state = r.nodal("contact_state")
    nx = r.nodal("contact_normal_x")
    slip = r.nodal("contact_slip_x")
    sets = {name: r.node_set(name + "_slave") for name in ("lower", "upper")}
except KeyError as e:
    zx.fail_read(CASE, str(e))
extra = {"steps_written": r.steps, "time": float(r.times[-1]), "P": P, "Q": Q}
tilt = 0.0
mean_slip = {}
for name, nodes in sets.items():
    active = [i for i in nodes if state[i] > 0.5]
    extra[name + "_active"] = len(active)
    extra[name + "_slipping"] = sum(1 for i in active if state[i] < 1.5)
    extra[name + "_sticking"] = sum(1 for i in active if state[i] > 1.5)
    tilt = max([tilt] + [abs(nx[i]) for i in active])
    mean_slip[name] = sum(abs(slip[i]) for i in active) / max(len(active), 1)
extra["max_normal_tilt"] = tilt
extra["upper_over_lower_mean_slip"] = mean_slip["upper"] / mean_slip["lower"] if mean_slip["lower"] > 0 else None
zx.report(CASE, "Q/P (reaction_top_x / -reaction_top_y), last step", Q / P if P > 0 else float("nan"), MU_LOWER,
          TOLERANCE, **extra)
