#!/usr/bin/python3
"""Check of tests/zoo/one_element_bodies_3d.xml: uniaxial compression of two
one-element cubes through a contact pair, at any number of ranks.

    /usr/bin/python3 tests/zoo/one_element_bodies_3d_check.py RESULT.e

Value: the support reaction |reaction_x0_x| (expected E eps A = 1050 N,
tolerance 1e-6 relative). Also required (condition): every slave node active
with the contact pressure of the current area, 1050 / (1 + nu eps)^2 (the
face widens by the lateral strain nu eps = 0.0015 and the mortar pressure is
the force per current area), to 1e-6 relative; the pair's contact force
equals the reaction.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "one_element_bodies_3d"
E, NU, STRAIN, AREA = 210000.0, 0.3, 0.005, 1.0
FORCE = E * STRAIN * AREA
PRESSURE = FORCE / (AREA * (1 + NU * STRAIN) ** 2)
TOLERANCE = 1e-6

r = zx.open_result(CASE, sys.argv)
try:
    pressure = r.nodal("contact_pressure")
    state = r.nodal("contact_state")
    slave = r.node_set("slave")
    reaction = r.glob_last("reaction_x0_x")
    contact = r.glob_last("contact_force_joint_x")
except KeyError as e:
    zx.fail_read(CASE, str(e))
active = [i for i in slave if state[i] > 0.5]
pressure_error = max(abs(pressure[i] - PRESSURE) / PRESSURE for i in slave)
balance_error = abs(abs(contact) - abs(reaction)) / FORCE
ok = len(active) == len(slave) and pressure_error <= TOLERANCE and balance_error <= TOLERANCE
zx.report(CASE, "|reaction_x0_x|, last step", abs(reaction), FORCE, TOLERANCE,
          condition=(ok, "all slave nodes active, pressure 1050 / (1 + nu eps)^2, contact force = reaction, to 1e-6"),
          steps_written=r.steps, slave_nodes=len(slave), active_slave_nodes=len(active),
          pressure_error=pressure_error, balance_error=balance_error)
