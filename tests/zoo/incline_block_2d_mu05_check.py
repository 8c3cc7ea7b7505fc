#!/usr/bin/python3
"""Check of tests/zoo/incline_block_2d_mu05.xml: block pushed up a 20 deg incline, mu = 0.5.

    /usr/bin/python3 tests/zoo/incline_block_2d_mu05_check.py RESULT.e

F / G at the last step against sin a + mu cos a (incline_block_check.py).
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.dont_write_bytecode = True
import incline_block_check  # noqa: E402

incline_block_check.check("incline_block_2d_mu05", 0.5, sys.argv)
