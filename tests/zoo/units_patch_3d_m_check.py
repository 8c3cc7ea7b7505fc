#!/usr/bin/python3
"""Check of tests/zoo/units_patch_3d_m.xml: punch pressed by p and slid, units m, N, Pa (N/m^2).

    /usr/bin/python3 tests/zoo/units_patch_3d_m_check.py RESULT.e

Q = reaction_top_x at the last step against mu p A = 300 N (1e-3 relative,
the deck's comment says why). Extras: the z contact force against p A (exact
by equilibrium), Q / P, the contact states and the largest normal tilt.
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "units_patch_3d_m"
MU = 0.3
PRESSURE = 10000000.0  # Pa
AREA = 0.0001  # m^2
TOLERANCE = 1e-3

r = zx.open_result(CASE, sys.argv)
try:
    Q = r.glob_last("reaction_top_x")
    Pz = abs(r.glob_last("contact_force_punch_z"))
    state = r.nodal("contact_state")
    nx, ny = r.nodal("contact_normal_x"), r.nodal("contact_normal_y")
    slave = r.node_set("slave")
except KeyError as e:
    zx.fail_read(CASE, str(e))
active = [i for i in slave if state[i] > 0.5]
zx.report(CASE, "Q = reaction_top_x [N], last step", Q, MU * PRESSURE * AREA, TOLERANCE,
          steps_written=r.steps, time=float(r.times[-1]), P_contact_z=Pz, P_expected=PRESSURE * AREA,
          Q_over_P=Q / Pz if Pz > 0 else None, active_slave_nodes=len(active),
          slipping_slave_nodes=sum(1 for i in active if state[i] < 1.5), slave_nodes=len(slave),
          max_normal_tilt=max((math.hypot(nx[i], ny[i]) for i in active), default=0.0))
