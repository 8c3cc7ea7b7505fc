#!/usr/bin/python3
"""Check of tests/zoo/neo_hookean_shear_3d.xml: rubber block sheared in gross slip.

    /usr/bin/python3 tests/zoo/neo_hookean_shear_3d_check.py RESULT.e

At the last step, every active slave node must slip, and the measured
Q / P (Q = reaction_top_x, P = -reaction_top_z) must equal the ratio Coulomb's
law predicts from the result's own contact fields, 1e-6 relative:
    F = sum_j D_j p_j (mu s_j - n_j),
D_j = contact_area (the node's mortar weight, current configuration), p_j the
pressure, n_j the nodal normal, s_j the unit tangential part of the node's
weighted slip (contact_weighted_slip, whose seed sign is that of the friction
traction on the slave); Q / P = -F_x / F_z. This is the block's momentum balance
(the top and the contact its only supports) with |tau_j| = mu p_j along the
slip at every node. Q / P is not mu itself: each node's force splits along its
own tilted normal (the deck's comment). Extras: Q / P against mu, the largest
tilt of the active normals and the pressure-weighted mean tilt.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "neo_hookean_shear_3d"
MU = 0.4
TOLERANCE = 1e-6

r = zx.open_result(CASE, sys.argv)
try:
    Q = r.glob_last("reaction_top_x")
    P = -r.glob_last("reaction_top_z")
    state = r.nodal("contact_state")
    pressure = r.nodal("contact_pressure")
    area = r.nodal("contact_area")
    normal = [r.nodal("contact_normal_" + c) for c in "xyz"]
    slip = [r.nodal("contact_weighted_slip_" + c) for c in "xyz"]
    slave = r.node_set("slave")
except KeyError as e:
    zx.fail_read(CASE, str(e))
active = [i for i in slave if state[i] > 0.5]
slipping = sum(1 for i in active if state[i] < 1.5)

force = [0.0, 0.0, 0.0]
for i in active:
    n = [normal[c][i] for c in range(3)]
    wn = sum(slip[c][i] * n[c] for c in range(3))
    s = [slip[c][i] - wn * n[c] for c in range(3)]
    length = math.sqrt(sum(v * v for v in s))
    if length > 0:
        s = [v / length for v in s]
    for c in range(3):
        force[c] += area[i] * pressure[i] * (MU * s[c] - n[c])
predicted = -force[0] / force[2] if force[2] != 0 else float("nan")

tilt = max((math.hypot(normal[0][i], normal[1][i]) for i in active), default=0.0)
weighted = sum(pressure[i] * normal[0][i] for i in active) / sum(pressure[i] for i in active) if active else 0.0
zx.report(CASE, "Q/P (reaction_top_x / -reaction_top_z) against Coulomb's sum_j D_j p_j (mu s_j - n_j), last step",
          Q / P if P > 0 else float("nan"), predicted, TOLERANCE,
          condition=(len(active) > 0 and slipping == len(active), "every active slave node slips"),
          steps_written=r.steps, time=float(r.times[-1]), P=P, Q=Q, Q_over_P_minus_mu=Q / P - MU if P > 0 else None,
          active_slave_nodes=len(active), slipping_slave_nodes=slipping, slave_nodes=len(slave),
          max_normal_tilt=tilt, p_weighted_tilt_x=weighted)
