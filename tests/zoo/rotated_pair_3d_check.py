#!/usr/bin/python3
"""Check of tests/zoo/rotated_pair_3d.xml: a pressed, sheared (stick) pair turned rigidly by 90 deg about y.

    /usr/bin/python3 tests/zoo/rotated_pair_3d_check.py RESULT.e

Compares the written step at t = 4 (pressed and sheared) with the last one,
which must be t = 13 (turned by 90 deg about y: (x, y, z) -> (z, y, -x)):
  value  max(|R(13) - Q R(4)| / |R(4)|, max_j |p_j(13) - p_j(4)| / max p(4))
         R = (reaction_top_x, _y, _z), p_j the slave nodes' contact_pressure
  expected 0, tolerance 1e-4 (absolute on these relative measures; the deck's
  comment says why); condition: the last step is t = 13.
Extras: each part, |R| at every written step from t = 4 on relative to |R(4)|,
the contact state counts at t = 4 and t = 13 and the number of slave nodes
whose state changed.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "rotated_pair_3d"
T_PRESSED, T_FINAL = 4.0, 13.0
TOLERANCE = 1e-4


def step_at(r, t):
    """1-based step written at pseudo time t, or None"""
    for k, tk in enumerate(r.times):
        if abs(tk - t) < 1e-9:
            return k + 1
    return None


r = zx.open_result(CASE, sys.argv)
import numpy as np  # noqa: E402

k0 = step_at(r, T_PRESSED)
if k0 is None:
    zx.fail_read(CASE, "no step written at t = %g (the pressed and sheared state)" % T_PRESSED)
try:
    R = np.array([r.glob("reaction_top_" + c) for c in "xyz"]).T  # steps x 3
    slave = r.node_set("slave")
    p0 = r.nodal("contact_pressure", step=k0)[slave]
    p1 = r.nodal("contact_pressure")[slave]
    s0 = r.nodal("contact_state", step=k0)[slave]
    s1 = r.nodal("contact_state")[slave]
except KeyError as e:
    zx.fail_read(CASE, str(e))
Q = np.array([[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [-1.0, 0.0, 0.0]])  # 90 deg about y
R0, R1 = R[k0 - 1], R[-1]
norm0 = float(np.linalg.norm(R0))
reaction_error = float(np.linalg.norm(R1 - Q @ R0)) / norm0
pressure_error = float(np.max(np.abs(p1 - p0))) / float(np.max(p0))
finished = abs(float(r.times[-1]) - T_FINAL) < 1e-9


def counts(s):
    return {"open": int(np.sum(s < 0.5)), "slip": int(np.sum((s > 0.5) & (s < 1.5))), "stick": int(np.sum(s > 1.5))}


zx.report(CASE, "max(|R(13) - Q R(4)| / |R(4)|, max |p(13) - p(4)| / max p(4)), Q = 90 deg about y",
          max(reaction_error, pressure_error), 0.0, TOLERANCE, relative=False,
          condition=(finished, "the last written step is t = %g" % T_FINAL),
          steps_written=r.steps, time=float(r.times[-1]), reaction_error=reaction_error,
          pressure_error=pressure_error, R_pressed=[float(v) for v in R0], R_final=[float(v) for v in R1],
          norm_R_over_norm_R4=[round(float(np.linalg.norm(R[k])) / norm0, 8) for k in range(k0 - 1, r.steps)],
          states_pressed=counts(s0), states_final=counts(s1), state_changes=int(np.sum(np.rint(s0) != np.rint(s1))))
