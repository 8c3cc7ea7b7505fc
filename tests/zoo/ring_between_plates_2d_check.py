#!/usr/bin/python3
"""Check of tests/zoo/ring_between_plates_2d.xml: a thin ring squeezed between two plates, mu = 0.3.

    /usr/bin/python3 tests/zoo/ring_between_plates_2d_check.py RESULT.e

Last written step (the deck's comment gives the derivations and tolerances):
  value     the largest symmetry defect: |R_top_y + R_bottom_y| / P,
            |R_top_x| / P, |R_bottom_x| / P, |reaction of ring_axis, ring_side| / P,
            max over ring nodes |u(-x, y) - (-u_x, u_y)(x, y)| / max |u|
            (P = -reaction_top_y), expected 0, tolerance 1e-4
  condition the shortening of the vertical diameter at mid-wall (nodes (0, +-1))
            against Roark's thick-ring formula, within 3 %, and the final time reached
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "ring_between_plates_2d"
E, NU = 210000.0, 0.3
R_MEAN, WALL = 1.0, 0.1
TOL_SYMMETRY = 1e-4
TOL_STIFFNESS = 0.03
FINAL_TIME = 1.0


def roark_shortening(P):
    """Roark table 9.2 case 1 (diametral loads P per unit depth), plane strain"""
    Ep = E / (1 - NU ** 2)
    G = E / (2 * (1 + NU))
    I = WALL ** 3 / 12.0
    A = WALL
    alpha = I / (A * R_MEAN ** 2)
    beta = 1.2 * Ep * I / (G * A * R_MEAN ** 2)
    k1, k2 = 1 - alpha + beta, 1 - alpha
    return P * R_MEAN ** 3 / (Ep * I) * (k1 * math.pi / 4 - 2 * k2 ** 2 / math.pi)


r = zx.open_result(CASE, sys.argv)
import numpy as np  # noqa: E402

try:
    X = r.coords
    ux, uy = r.nodal("displacement_x"), r.nodal("displacement_y")
    rx, ry = r.nodal("reaction_x"), r.nodal("reaction_y")
    Rt = (r.glob_last("reaction_top_x"), r.glob_last("reaction_top_y"))
    Rb = (r.glob_last("reaction_bottom_x"), r.glob_last("reaction_bottom_y"))
    axis, side = r.node_set("ring_axis"), r.node_set("ring_side")
except KeyError as e:
    zx.fail_read(CASE, str(e))
P = -Rt[1]
from netCDF4 import Dataset  # noqa: E402

with Dataset(r.path) as ds:  # the ring's nodes: those of the block `ring`
    ds.set_auto_mask(False)
    names = zx._names(ds, "eb_names")
    if "ring" not in names:
        zx.fail_read(CASE, "no element block 'ring'")
    ring = np.unique(np.array(ds.variables["connect%d" % (names.index("ring") + 1)][:], dtype=int) - 1)

umax = float(np.max(np.hypot(ux[ring], uy[ring])))
Xr = X[ring]


def nearest(point):
    """the ring node nearest to `point` and its distance"""
    d = np.hypot(Xr[:, 0] - point[0], Xr[:, 1] - point[1])
    k = int(np.argmin(d))
    return int(ring[k]), float(d[k])


mirror = 0.0
for i in ring:
    j, dist = nearest((-X[i, 0], X[i, 1]))
    if dist > 1e-6:
        zx.fail_read(CASE, "ring node %d has no mirror image about x = 0" % i)
    mirror = max(mirror, math.hypot(ux[j] + ux[i], uy[j] - uy[i]))
parts = {
    "vertical_balance": abs(Rt[1] + Rb[1]) / P,
    "top_tangential": abs(Rt[0]) / P,
    "bottom_tangential": abs(Rb[0]) / P,
    "point_reactions": max(max(abs(rx[i]) for i in axis), max(abs(ry[i]) for i in side)) / P,
    "mirror_defect": mirror / umax,
}
(top_mid, d_top), (bot_mid, d_bot) = nearest((0.0, 1.0)), nearest((0.0, -1.0))
if max(d_top, d_bot) > 1e-6:
    zx.fail_read(CASE, "no ring node at (0, +-1)")
shortening = float(uy[bot_mid] - uy[top_mid])
expected_shortening = roark_shortening(P)
thin_ring = 0.1488 * P * R_MEAN ** 3 / (E / (1 - NU ** 2) * WALL ** 3 / 12.0)
stiffness_error = abs(shortening / expected_shortening - 1.0)
finished = abs(float(r.times[-1]) - FINAL_TIME) < 1e-9
zx.report(CASE, "largest symmetry defect (reaction balance, tangential reactions, point reactions, mirror u)",
          max(parts.values()), 0.0, TOL_SYMMETRY, relative=False,
          condition=(finished and stiffness_error <= TOL_STIFFNESS,
                     "final time reached and |Delta / Delta_Roark - 1| <= %g" % TOL_STIFFNESS),
          steps_written=r.steps, time=float(r.times[-1]), P=P, parts=parts, shortening=shortening,
          shortening_roark=expected_shortening, shortening_thin_ring=thin_ring,
          shortening_over_roark=shortening / expected_shortening)
