#!/usr/bin/python3
"""Check of tests/zoo/neo_hookean_shear_3d.xml: rubber block sheared in gross slip.

    /usr/bin/python3 tests/zoo/neo_hookean_shear_3d_check.py RESULT.e

Q / P at the last step (Q = reaction_top_x, P = -reaction_top_z) against
mu = 0.4, 3e-2 relative (the deck's comment says why). Extras: the slave
nodes' contact states, the largest tilt of the active nodes' normals
(sqrt(n_x^2 + n_y^2)), the pressure-weighted mean tilt sum(p n_x) / sum(p) and
the first-order estimate (1 + mu^2) |that| / mu of the relative error it causes.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "neo_hookean_shear_3d"
MU = 0.4
TOLERANCE = 3e-2

r = zx.open_result(CASE, sys.argv)
try:
    Q = r.glob_last("reaction_top_x")
    P = -r.glob_last("reaction_top_z")
    state = r.nodal("contact_state")
    nx, ny = r.nodal("contact_normal_x"), r.nodal("contact_normal_y")
    slave = r.node_set("slave")
except KeyError as e:
    zx.fail_read(CASE, str(e))
active = [i for i in slave if state[i] > 0.5]
slipping = sum(1 for i in active if state[i] < 1.5)
tilt = max((math.hypot(nx[i], ny[i]) for i in active), default=0.0)
pressure = r.nodal("contact_pressure")
weighted = sum(pressure[i] * nx[i] for i in active) / sum(pressure[i] for i in active) if active else 0.0
zx.report(CASE, "Q/P (reaction_top_x / -reaction_top_z), last step", Q / P if P > 0 else float("nan"), MU,
          TOLERANCE, steps_written=r.steps, time=float(r.times[-1]), P=P, Q=Q, active_slave_nodes=len(active),
          slipping_slave_nodes=slipping, slave_nodes=len(slave), max_normal_tilt=tilt,
          p_weighted_tilt_x=weighted, tilt_estimate_relative=(1 + MU * MU) * abs(weighted) / MU)
