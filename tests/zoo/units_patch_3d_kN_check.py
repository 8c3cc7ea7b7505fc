#!/usr/bin/python3
"""Check of tests/zoo/units_patch_3d_kN.xml: punch pressed by p and slid, units mm, kN, GPa (kN/mm^2).

    /usr/bin/python3 tests/zoo/units_patch_3d_kN_check.py RESULT.e

Q = reaction_top_x at the last step against mu p A = 0.3 kN (units_patch_check.py).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import units_patch_check  # noqa: E402

units_patch_check.check("units_patch_3d_kN", 0.01, 100.0, sys.argv, force_unit="kN")
