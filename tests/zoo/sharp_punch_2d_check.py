#!/usr/bin/python3
"""Check of tests/zoo/sharp_punch_2d.xml: flat punch slid in gross slip.

    /usr/bin/python3 tests/zoo/sharp_punch_2d_check.py RESULT.e

Q / P at the last step (Q = reaction_top_x, P = -reaction_top_y) against
mu = 0.3, 1e-3 relative (the deck's comment says why). Extras: the slave
nodes' contact states, the largest normal tilt |n_x| of the active nodes,
the corner nodes' share of P.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "sharp_punch_2d"
MU = 0.3
TOLERANCE = 1e-3

r = zx.open_result(CASE, sys.argv)
try:
    Q = r.glob_last("reaction_top_x")
    P = -r.glob_last("reaction_top_y")
    state = r.nodal("contact_state")
    nx = r.nodal("contact_normal_x")
    pressure = r.nodal("contact_pressure")
    slave = r.node_set("slave")
except KeyError as e:
    zx.fail_read(CASE, str(e))
active = [i for i in slave if state[i] > 0.5]
slipping = sum(1 for i in active if state[i] < 1.5)
x = r.coords[:, 0]
corners = [i for i in slave if abs(abs(x[i]) - 5.0) < 1e-9]
mean_pressure = P / 10.0
zx.report(CASE, "Q/P (reaction_top_x / -reaction_top_y), last step", Q / P if P > 0 else float("nan"), MU, TOLERANCE,
          steps_written=r.steps, time=float(r.times[-1]), P=P, Q=Q, active_slave_nodes=len(active),
          slipping_slave_nodes=slipping, slave_nodes=len(slave),
          max_normal_tilt=max((abs(nx[i]) for i in active), default=0.0),
          corner_pressure_over_mean=[float(pressure[i] / mean_pressure) for i in corners])
