"""The check shared by the incline block cases (incline_block_2d_mu02, _mu05,
incline_block_skin_2d): F / G at the last step (F = reaction_back_x, G = B x
area = 400 N/mm) against sin a + mu cos a (gross slip; the decks' comments give
the derivation and the tolerance). Extras: the contact state counts of the
bottom's nodes (set `slave`), the largest tilt |n_x| of the active nodes'
normals (what the tolerance allows for), and each sticking node's x, pressure
and tangential traction (none should stick in gross slip). With `skin`, the
name of a slave set that holds the bottom and the block's ends, a second
condition: every node of the bottom in contact at the last step (as in
incline_block_2d_mu02, whose slave set is the bottom alone: 49 of 49; with
normals averaged across the corners, the two corner nodes never close) and
no node of the ends.
"""
import math

import zoo_exodus as zx

ALPHA = math.radians(20.0)
G = 1.0 * 40.0 * 10.0  # B x block area, per unit thickness
TOLERANCE = 1e-3


def check(case, mu, argv, skin=None):
    r = zx.open_result(case, argv)
    try:
        F = r.glob_last("reaction_back_x")
        state = r.nodal("contact_state")
        nx = r.nodal("contact_normal_x")
        pressure = r.nodal("contact_pressure")
        tx = r.nodal("contact_tangential_traction_x")
        slave = r.node_set("slave")
        ends = sorted(set(r.node_set(skin)) - set(slave)) if skin else []
    except KeyError as e:
        zx.fail_read(case, str(e))
    active = [i for i in slave if state[i] > 0.5]
    slipping = sum(1 for i in active if state[i] < 1.5)
    # a sticking node in gross slip is wrong; list each with its position, pressure, traction
    sticking = [[float(r.coords[i, 0]), float(pressure[i]), float(tx[i])] for i in active if state[i] > 1.5]
    extra = {}
    condition = None
    if skin:
        touching = [int(i) + 1 for i in ends if state[i] > 0.5]
        open_bottom = [int(i) + 1 for i in slave if state[i] < 0.5]
        condition = (not touching and not open_bottom,
                     "every node of the bottom (set slave) in contact, no node of the ends (set %s less slave)" % skin)
        extra = {"end_nodes": len(ends), "end_nodes_in_contact": touching, "bottom_nodes_open": open_bottom}
    zx.report(case, "F/G (reaction_back_x / G), last step", F / G, math.sin(ALPHA) + mu * math.cos(ALPHA), TOLERANCE,
              condition=condition, steps_written=r.steps, time=float(r.times[-1]), active_slave_nodes=len(active),
              slipping_slave_nodes=slipping, sticking_nodes_x_p_tx=sticking,
              max_normal_tilt=max((abs(nx[i]) for i in active), default=0.0), **extra)
