"""The check shared by the pressed and slid punch cases (units_patch_3d_mm,
_m, _kN, units_patch_skin_3d): Q = reaction_top_x at the last step against
mu p A (300 N; 1e-3 relative, the decks' comments say why). Extras: the z
contact force against p A (exact by equilibrium), Q / P, the contact states
and the largest normal tilt. With `skin`, the name of a slave set that holds
the punch's bottom (set `slave`) and its sides, a second condition: no node
of the sides in contact, and every node in contact with a normal within 1e-3
of the vertical (the interface tilts by strains ~1e-4; an edge node whose
normal averaged the bottom and a side would be 0.71 off). Not "every bottom
node in contact": on HEX20 / HEX27 cells units_patch_3d_mm itself ends with
9 / 14 nodes of the trailing edge open.
"""
import math

import zoo_exodus as zx

MU = 0.3
TOLERANCE = 1e-3


def check(case, pressure, area, argv, skin=None, force_unit="N"):
    r = zx.open_result(case, argv)
    try:
        Q = r.glob_last("reaction_top_x")
        Pz = abs(r.glob_last("contact_force_punch_z"))
        state = r.nodal("contact_state")
        nx, ny = r.nodal("contact_normal_x"), r.nodal("contact_normal_y")
        slave = r.node_set("slave")
        sides = sorted(set(r.node_set(skin)) - set(slave)) if skin else []
    except KeyError as e:
        zx.fail_read(case, str(e))
    active = [i for i in slave if state[i] > 0.5]
    tilt = max((math.hypot(nx[i], ny[i]) for i in active), default=0.0)
    condition = None
    extra = {}
    if skin:
        touching = [int(i) + 1 for i in sides if state[i] > 0.5]
        tilted = [int(i) + 1 for i in range(len(state)) if state[i] > 0.5 and math.hypot(nx[i], ny[i]) > 1e-3]
        condition = (not touching and not tilted,
                     "no node of the sides (set %s less slave) in contact, every contact normal within 1e-3 of "
                     "the vertical" % skin)
        extra = {"side_nodes": len(sides), "side_nodes_in_contact": touching, "tilted_contact_nodes": tilted}
    zx.report(case, "Q = reaction_top_x [%s], last step" % force_unit, Q, MU * pressure * area, TOLERANCE, condition=condition,
              steps_written=r.steps, time=float(r.times[-1]), P_contact_z=Pz, P_expected=pressure * area,
              Q_over_P=Q / Pz if Pz > 0 else None, active_slave_nodes=len(active),
              slipping_slave_nodes=sum(1 for i in active if state[i] < 1.5), slave_nodes=len(slave),
              max_normal_tilt=tilt, **extra)
