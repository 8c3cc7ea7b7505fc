#!/usr/bin/python3
"""Check of tests/zoo/press_fit_2d.xml: ring shrunk on a disc (Lame interference), mu = 0.2.

    /usr/bin/python3 tests/zoo/press_fit_2d_check.py RESULT.e

Last written step: the mean contact pressure of the slave nodes, weighted by
their nodal lengths L_j (half of each adjacent slave segment: the integral of
the linear shape function), against Lame's p (the deck's comment gives the
formula and the 1 % tolerance); condition: every slave node active.
Extras: the largest nodal deviation from p, the largest |tangential traction| / p,
the pair's contact force against p b (the resultant on a quarter arc is p b (1, 1)).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "press_fit_2d"
E, NU = 210000.0, 0.3
A_IN, B, C = 0.5, 1.0, 2.0
DELTA = 1e-3
TOLERANCE = 0.01


def lame_pressure():
    ring = ((1 - 2 * NU) * B ** 2 + C ** 2) / (C ** 2 - B ** 2)
    disc = ((1 - 2 * NU) * B ** 2 + A_IN ** 2) / (B ** 2 - A_IN ** 2)
    return E * DELTA / ((1 + NU) * B * (ring + disc))


r = zx.open_result(CASE, sys.argv)
try:
    X = r.coords
    slave = r.node_set("slave")
    p = r.nodal("contact_pressure")
    state = r.nodal("contact_state")
    tx, ty = r.nodal("contact_tangential_traction_x"), r.nodal("contact_tangential_traction_y")
    fx = r.glob_last("contact_force_fit_x")
except KeyError as e:
    zx.fail_read(CASE, str(e))
L = zx.side_weights(r.path, slave, X[:, 0], X[:, 1])
total = sum(L.get(j, 0.0) for j in slave)
p_mean = sum(p[j] * L.get(j, 0.0) for j in slave) / total
p_lame = lame_pressure()
active = [j for j in slave if state[j] > 0.5]
zx.report(CASE, "length-weighted mean contact pressure on the slave arc [MPa]", p_mean, p_lame, TOLERANCE,
          condition=(len(active) == len(slave), "every slave node active"),
          steps_written=r.steps, time=float(r.times[-1]), active_slave_nodes=len(active), slave_nodes=len(slave),
          max_nodal_deviation=max(abs(p[j] / p_lame - 1) for j in slave),
          max_tangential_over_p=max(math.hypot(tx[j], ty[j]) / p[j] for j in active) if active else None,
          contact_force_x_over_p_b=abs(fx) / (p_lame * B))
