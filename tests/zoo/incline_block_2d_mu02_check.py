#!/usr/bin/python3
"""Check of tests/zoo/incline_block_2d_mu02.xml: block pushed up a 20 deg incline, mu = 0.2.

    /usr/bin/python3 tests/zoo/incline_block_2d_mu02_check.py RESULT.e

F / G at the last step (F = reaction_back_x, G = B x area = 400 N/mm) against
sin a + mu cos a (gross slip; the deck's comment gives the derivation and the
tolerance). Extras: the contact state counts of the slave nodes, the largest
tilt |n_x| of the active nodes' normals (what the tolerance allows for), and
each sticking slave node's x, pressure and tangential traction (none should
stick in gross slip).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "incline_block_2d_mu02"
MU = 0.2
ALPHA = math.radians(20.0)
G = 1.0 * 40.0 * 10.0  # B x block area, per unit thickness
TOLERANCE = 1e-3

r = zx.open_result(CASE, sys.argv)
try:
    F = r.glob_last("reaction_back_x")
    state = r.nodal("contact_state")
    nx = r.nodal("contact_normal_x")
    pressure = r.nodal("contact_pressure")
    tx = r.nodal("contact_tangential_traction_x")
    slave = r.node_set("slave")
except KeyError as e:
    zx.fail_read(CASE, str(e))
active = [i for i in slave if state[i] > 0.5]
slipping = sum(1 for i in active if state[i] < 1.5)
# a sticking node in gross slip is wrong; list each with its position, pressure, traction
sticking = [[float(r.coords[i, 0]), float(pressure[i]), float(tx[i])] for i in active if state[i] > 1.5]
zx.report(CASE, "F/G (reaction_back_x / G), last step", F / G, math.sin(ALPHA) + MU * math.cos(ALPHA), TOLERANCE,
          steps_written=r.steps, time=float(r.times[-1]), active_slave_nodes=len(active),
          slipping_slave_nodes=slipping, sticking_nodes_x_p_tx=sticking, max_normal_tilt=max((abs(nx[i]) for i in active), default=0.0))
