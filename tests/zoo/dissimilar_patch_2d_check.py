#!/usr/bin/python3
"""Check of tests/zoo/dissimilar_patch_2d.xml: the frictional patch test across
an E ratio of 1000 and a mesh size ratio of ~3.

    /usr/bin/python3 tests/zoo/dissimilar_patch_2d_check.py RESULT.e

Value: the largest |contact_pressure - p| / p over the slave nodes at the last
step (expected 0, tolerance 1e-6). Also required (condition): every slave node
active and sticking, |contact_tangential_traction_x + tau| / p <= 1e-6 at
every slave node, and |reaction_bottom_x + tau| / tau, |reaction_bottom_y - p| / p
<= 1e-6 (the deck's comment gives the exact state and the tolerance).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "dissimilar_patch_2d"
P, TAU, LENGTH = 1.0, 0.15, 1.0
TOLERANCE = 1e-6

r = zx.open_result(CASE, sys.argv)
try:
    pressure = r.nodal("contact_pressure")
    state = r.nodal("contact_state")
    tx = r.nodal("contact_tangential_traction_x")
    slave = r.node_set("slave")
    rx, ry = r.glob_last("reaction_bottom_x"), r.glob_last("reaction_bottom_y")
except KeyError as e:
    zx.fail_read(CASE, str(e))
active = [i for i in slave if state[i] > 0.5]
sticking = [i for i in active if state[i] > 1.5]
pressure_error = max(abs(pressure[i] - P) / P for i in slave)
traction_error = max(abs(tx[i] + TAU) / P for i in slave)
reaction_error = max(abs(rx + TAU * LENGTH) / (TAU * LENGTH), abs(ry - P * LENGTH) / (P * LENGTH))
ok = len(active) == len(slave) and len(sticking) == len(slave) and traction_error <= TOLERANCE \
    and reaction_error <= TOLERANCE
zx.report(CASE, "max |contact_pressure - p| / p over the slave nodes, last step", pressure_error, 0.0, TOLERANCE,
          relative=False,
          condition=(ok, "all slave nodes active and sticking; traction -tau and reaction_bottom = (-tau, p) to 1e-6"),
          steps_written=r.steps, slave_nodes=len(slave), active_slave_nodes=len(active),
          sticking_slave_nodes=len(sticking), traction_error=traction_error, reaction_error=reaction_error,
          reaction_bottom=[rx, ry])
