#!/usr/bin/python3
"""Check of tests/zoo/cylinder_rolling_2d.xml: a pressed cylinder rolled without slip, mu = 0.5.

    /usr/bin/python3 tests/zoo/cylinder_rolling_2d_check.py RESULT.e

Over the written rolling steps (t > 2):
  value     max |Q| / (mu P), Q = reaction_bottom_x, P = |reaction_bottom_y|
  expected  0 (free rolling of elastically similar bodies, no tangential traction)
  tolerance Carter's bound for the largest creep the prescribed rolling radius
            can impose, xi = delta / R: 1 - (1 - delta / (mu a))^2 with the Hertz
            half-width a = sqrt(4 P R / (pi E*)) at the end of the pressing (t = 2)
  condition every rolling step has sticking slave nodes, and the final time reached
Extras: Q / (mu P) and the stick / slip node counts per rolling step, a, the
active nodes' extent at t = 2 (the measured contact width).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "cylinder_rolling_2d"
MU = 0.5
R_CYL = 10.0
DELTA = 0.1
E, NU = 210000.0, 0.3
T_PRESSED, FINAL_TIME = 2.0, 17.0

r = zx.open_result(CASE, sys.argv)
import numpy as np  # noqa: E402

try:
    Qs = r.glob("reaction_bottom_x")
    Ps = np.abs(r.glob("reaction_bottom_y"))
    slave = r.node_set("slave")
    states = [r.nodal("contact_state", step=k + 1)[slave] for k in range(r.steps)]
except KeyError as e:
    zx.fail_read(CASE, str(e))
pressed = [k for k, t in enumerate(r.times) if abs(t - T_PRESSED) < 1e-9]
if not pressed:
    zx.fail_read(CASE, "no step written at t = %g (the end of the pressing)" % T_PRESSED)
k0 = pressed[0]
P0 = float(Ps[k0])
E_star = E / (2 * (1 - NU ** 2))
a = math.sqrt(4 * P0 * R_CYL / (math.pi * E_star))
bound = 1 - (1 - DELTA / (MU * a)) ** 2 if DELTA < MU * a else 1.0
x_active = r.coords[slave, 0][states[k0] > 0.5]
rolling = [k for k, t in enumerate(r.times) if t > T_PRESSED + 1e-9]
ratios = [abs(float(Qs[k])) / (MU * float(Ps[k])) for k in rolling]
sticks = [int(np.sum(states[k] > 1.5)) for k in rolling]
slips = [int(np.sum((states[k] > 0.5) & (states[k] < 1.5))) for k in rolling]
finished = abs(float(r.times[-1]) - FINAL_TIME) < 1e-9
value = max(ratios) if ratios else float("nan")
zx.report(CASE, "max over the rolling steps of |Q| / (mu P) (reactions of `bottom`)", value, 0.0, bound,
          relative=False,
          condition=(finished and bool(rolling) and min(sticks) > 0,
                     "final time reached and sticking slave nodes at every rolling step"),
          steps_written=r.steps, time=float(r.times[-1]), P_pressed=P0, hertz_half_width=a,
          active_extent_pressed=[float(x_active.min()), float(x_active.max())] if len(x_active) else None,
          Q_over_muP=[round(v, 6) for v in ratios], stick_nodes=sticks, slip_nodes=slips)
