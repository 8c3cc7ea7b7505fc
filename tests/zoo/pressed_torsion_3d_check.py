#!/usr/bin/python3
"""Check of tests/zoo/pressed_torsion_3d.xml: a pressed cylinder twisted into gross slip, mu = 0.3.

    /usr/bin/python3 tests/zoo/pressed_torsion_3d_check.py RESULT.e

Last written step (the deck's comment gives the derivation and tolerances):
  value     T = |sum over `top` of x R_y - y R_x| (torque of the reactions)
  expected  mu sum_j p_j r_j A_j over the slave nodes (contact_pressure p_j,
            r_j the distance to the z axis, A_j = integral of the node's
            shape function over the slave faces: HEX8, HEX20 or HEX27 cells;
            on HEX20's QUAD8 faces the transformed shape function and the
            transformed position, where the node's contact force acts)
            tolerance 1e-3
  condition T against Lubkin on the meshed disc, mu P int(r dA) / A
            (P = -reaction_top_z, = (2/3) mu P a on the exact disc), 1.5 %
Extras: T / ((2/3) mu P a), the torque of the tangential tractions, sum p_j A_j
against P, contact state counts, and the expected T only when the run reached
the deck's final time (earlier steps are not in gross slip).
"""
import math
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "pressed_torsion_3d"
MU = 0.3
A_RADIUS = 1.0
FINAL_TIME = 12.0
TOL_CONSERVATION = 1e-3
TOL_LUBKIN = 0.015
HEX_FACES = ((0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (0, 4, 7, 3), (0, 3, 2, 1), (4, 5, 6, 7))
G4 = [(-0.8611363115940526, 0.3478548451374538), (-0.3399810435848563, 0.6521451548625461),
      (0.3399810435848563, 0.6521451548625461), (0.8611363115940526, 0.3478548451374538)]


def slave_faces(path, nodes, xyz):
    """faces on the slave surface of the hexahedral cells whose corners are all in
    `nodes`: 0-based node lists, the four corners in cyclic order, then (HEX20,
    HEX27) the nodes of the sides 01, 12, 23, 30 and (HEX27) the face centre.
    The cell's node nearest to a side's midpoint (to the corners' mean) is that
    side's (the face's centre) node: no table of the Exodus numbering needed."""
    import numpy as np
    inside = set(int(i) for i in nodes)
    faces = []

    def nearest(candidates, point):
        return min(candidates, key=lambda v: float(np.linalg.norm(xyz[v] - point)))

    for conn in zx.connectivities(path):
        for cell in conn:
            extra = [int(v) for v in cell[8:]]
            for f in HEX_FACES:
                face = [int(cell[k]) for k in f]
                if not all(v in inside for v in face):
                    continue
                if extra:
                    face += [nearest(extra, 0.5 * (xyz[face[k]] + xyz[face[(k + 1) % 4]])) for k in range(4)]
                if len(cell) == 27:
                    face.append(nearest(extra, xyz[face[:4]].mean(axis=0)))
                faces.append(face)
    return faces


CORNERS = ((-1, -1), (1, -1), (1, 1), (-1, 1))
SIDES = ((0, -1), (1, 0), (0, 1), (-1, 0))


def shape(count, xi, eta):
    """values and xi-, eta-derivatives of the QUAD4 / QUAD8 / QUAD9 shape functions
    in the node order of slave_faces"""
    def lagrange(a, t):  # 1D quadratic through -1, 0, 1, and its derivative
        return {-1: (0.5 * t * (t - 1), t - 0.5), 0: (1 - t * t, -2 * t), 1: (0.5 * t * (t + 1), t + 0.5)}[a]

    if count == 4:
        N = [0.25 * (1 + a * xi) * (1 + b * eta) for a, b in CORNERS]
        dx = [0.25 * a * (1 + b * eta) for a, b in CORNERS]
        de = [0.25 * b * (1 + a * xi) for a, b in CORNERS]
        return N, dx, de
    if count == 8:
        N = [0.25 * (1 + a * xi) * (1 + b * eta) * (a * xi + b * eta - 1) for a, b in CORNERS]
        dx = [0.25 * a * (1 + b * eta) * (2 * a * xi + b * eta) for a, b in CORNERS]
        de = [0.25 * b * (1 + a * xi) * (a * xi + 2 * b * eta) for a, b in CORNERS]
        for a, b in SIDES:
            if a == 0:
                N.append(0.5 * (1 - xi * xi) * (1 + b * eta))
                dx.append(-xi * (1 + b * eta))
                de.append(0.5 * b * (1 - xi * xi))
            else:
                N.append(0.5 * (1 + a * xi) * (1 - eta * eta))
                dx.append(0.5 * a * (1 - eta * eta))
                de.append(-eta * (1 + a * xi))
        return N, dx, de
    N, dx, de = [], [], []
    for a, b in CORNERS + SIDES + ((0, 0),):
        (la, dla), (lb, dlb) = lagrange(a, xi), lagrange(b, eta)
        N.append(la * lb)
        dx.append(dla * lb)
        de.append(la * dlb)
    return N, dx, de


# QUAD8 slave faces take the transformed basis (src/coulomb/contact/mortar/
# DualBasis.hpp): N~_c = N_c + ALPHA (N_e + N_e') at a corner, N~_e = (1 -
# 2 ALPHA) N_e at a side node; a node's contact force D_j p_j then acts at its
# transformed position x~_j (x~_e = (x_e - ALPHA (x_a + x_b)) / (1 - 2 ALPHA)
# on side e = (a, b), x~_c = x_c): sum_i x_i x f_i = sum_j x~_j x F~_j for
# f = T^-T F~, x = T x~.
ALPHA = 0.2


def trial(N, count):
    """the shape functions a node's multiplier force is weighted with: N itself,
    or for QUAD8 the transformed N~"""
    if count != 8:
        return N
    Nt = list(N)
    for k in range(4):  # side k joins corners k and k + 1
        Nt[4 + k] = (1 - 2 * ALPHA) * N[4 + k]
        Nt[k] += ALPHA * (N[4 + k] + N[4 + (k + 3) % 4])
    return Nt


def action_points(xyz, faces):
    """per node its point of action: x~_e for a QUAD8 side node, else x"""
    points = {}
    for face in faces:
        for k, v in enumerate(face):
            if len(face) == 8 and k >= 4:
                a, b = face[k - 4], face[(k - 3) % 4]
                points[v] = (xyz[v] - ALPHA * (xyz[a] + xyz[b])) / (1 - 2 * ALPHA)
            else:
                points.setdefault(v, xyz[v])
    return points


def face_integrals(xyz, faces):
    """A_j = int N_j dA per node (N~_j on QUAD8 faces), and int dA, int r dA over
    the faces (4 x 4 Gauss, the faces' own shape functions: QUAD4, QUAD8 or QUAD9)"""
    import numpy as np
    area = {}
    total, moment = 0.0, 0.0
    for face in faces:
        x = xyz[face]
        for xi, wx in G4:
            for eta, wy in G4:
                N, dxi, deta = (np.array(v) for v in shape(len(face), xi, eta))
                J = np.linalg.norm(np.cross(dxi @ x, deta @ x)) * wx * wy
                p = N @ x
                total += J
                moment += J * math.hypot(p[0], p[1])
                for k, v in enumerate(face):
                    area[v] = area.get(v, 0.0) + trial(N, len(face))[k] * J
    return area, total, moment


r = zx.open_result(CASE, sys.argv)
try:
    X = r.coords
    top = r.node_set("top")
    slave = r.node_set("slave")
    Rx, Ry = r.nodal("reaction_x"), r.nodal("reaction_y")
    P = -r.glob_last("reaction_top_z")
    p = r.nodal("contact_pressure")
    state = r.nodal("contact_state")
    tx, ty = r.nodal("contact_tangential_traction_x"), r.nodal("contact_tangential_traction_y")
except KeyError as e:
    zx.fail_read(CASE, str(e))
faces = slave_faces(r.path, slave, X)
if not faces:
    zx.fail_read(CASE, "no slave faces found in the connectivity")
A, area, moment = face_integrals(X, faces)

T = abs(sum(X[i, 0] * Ry[i] - X[i, 1] * Rx[i] for i in top))
Xa = action_points(X, faces)
T_friction = MU * sum(p[j] * math.hypot(Xa[j][0], Xa[j][1]) * A[j] for j in slave)
T_traction = abs(sum(A[j] * (Xa[j][0] * ty[j] - Xa[j][1] * tx[j]) for j in slave))
P_contact = sum(p[j] * A[j] for j in slave)
lubkin_mesh = MU * P * moment / area
lubkin_disc = 2.0 / 3.0 * MU * P * A_RADIUS
active = [j for j in slave if state[j] > 0.5]
slipping = sum(1 for j in active if state[j] < 1.5)
lubkin_error = abs(T / lubkin_mesh - 1.0) if lubkin_mesh > 0 else float("inf")
finished = abs(float(r.times[-1]) - FINAL_TIME) < 1e-9
zx.report(CASE, "|torque of the top reactions| vs mu sum p_j r_j A_j (last step, gross slip)", T, T_friction,
          TOL_CONSERVATION,
          condition=(finished and lubkin_error <= TOL_LUBKIN,
                     "final time reached and |T / (mu P int r dA / A) - 1| <= %g (Lubkin on the meshed disc)"
                     % TOL_LUBKIN),
          steps_written=r.steps, time=float(r.times[-1]), P=P, sum_p_A=P_contact, lubkin_mesh=lubkin_mesh,
          lubkin_disc=lubkin_disc, T_over_lubkin_mesh=T / lubkin_mesh if lubkin_mesh else None,
          T_over_lubkin_disc=T / lubkin_disc if lubkin_disc else None, torque_of_tangential_tractions=T_traction,
          active_slave_nodes=len(active), slipping_slave_nodes=slipping, slave_nodes=len(slave))
