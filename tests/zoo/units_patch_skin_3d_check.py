#!/usr/bin/python3
"""Check of tests/zoo/units_patch_skin_3d.xml: units_patch_3d_mm with the
punch's bottom and four sides in one slave surface (set `skin`).

    /usr/bin/python3 tests/zoo/units_patch_skin_3d_check.py RESULT.e

Q = reaction_top_x at the last step against mu p A = 300 N
(units_patch_check.py), no side node in contact and every contact normal
within 1e-3 of the vertical.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import units_patch_check  # noqa: E402

units_patch_check.check("units_patch_skin_3d", 10.0, 100.0, sys.argv, skin="skin")
