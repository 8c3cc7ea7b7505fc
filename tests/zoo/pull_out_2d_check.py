#!/usr/bin/python3
"""Check of tests/zoo/pull_out_2d.xml: a bar pulled out of a pressed sleeve in gross slip, mu = 0.3.

    /usr/bin/python3 tests/zoo/pull_out_2d_check.py RESULT.e

Last written step (the deck's comment gives the derivation and the tolerance):
  value     F = |reaction_pull_x| (the pull force)
  expected  mu |reaction_outer_y| (mu N, N from the sleeve's y equilibrium), 1e-3 relative
  condition F against mu sum_j p_j L_j (the integrated contact pressure, L_j the
            slave node's int N_j ds on the deformed sleeve bottom) within 1e-3, every
            active slave node slipping, and the final time reached
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import zoo_exodus as zx  # noqa: E402

CASE = "pull_out_2d"
MU = 0.3
TOLERANCE = 1e-3
FINAL_TIME = 12.0


r = zx.open_result(CASE, sys.argv)
try:
    slave = r.node_set("slave")
    x = r.coords[:, 0] + r.nodal("displacement_x")
    y = r.coords[:, 1] + r.nodal("displacement_y")
    p = r.nodal("contact_pressure")
    state = r.nodal("contact_state")
    F = abs(r.glob_last("reaction_pull_x"))
    N_reaction = abs(r.glob_last("reaction_outer_y"))
except KeyError as e:
    zx.fail_read(CASE, str(e))
L = zx.side_weights(r.path, slave, x, y)  # on the deformed sleeve bottom
N_pressure = sum(p[j] * L.get(j, 0.0) for j in slave)
active = [j for j in slave if state[j] > 0.5]
slipping = sum(1 for j in active if state[j] < 1.5)
pressure_error = abs(F / (MU * N_pressure) - 1.0) if N_pressure > 0 else float("inf")
finished = abs(float(r.times[-1]) - FINAL_TIME) < 1e-9
zx.report(CASE, "pull force |reaction_pull_x| vs mu |reaction_outer_y| (last step, gross slip)", F, MU * N_reaction,
          TOLERANCE,
          condition=(finished and pressure_error <= TOLERANCE and active and slipping == len(active),
                     "final time reached, |F / (mu sum p_j L_j) - 1| <= %g, every active slave node slipping"
                     % TOLERANCE),
          steps_written=r.steps, time=float(r.times[-1]), N_reaction=N_reaction, N_pressure=N_pressure,
          F_over_mu_N_pressure=F / (MU * N_pressure) if N_pressure > 0 else None,
          active_slave_nodes=len(active), slipping_slave_nodes=slipping, slave_nodes=len(slave))
