#!/usr/bin/python3
"""Check of tests/zoo/incline_block_skin_2d.xml: incline_block_2d_mu02 with the
block's bottom and both ends in one slave surface (set `skin`).

    /usr/bin/python3 tests/zoo/incline_block_skin_2d_check.py RESULT.e

F / G at the last step against sin a + mu cos a (incline_block_check.py), and
no node of the block's ends in contact.
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import incline_block_check  # noqa: E402

incline_block_check.check("incline_block_skin_2d", 0.2, sys.argv, skin="skin")
