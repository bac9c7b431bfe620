"""test_io.py and test_io_format13.py run by Blender's Python, where numpy exists (the vectorised geometry paths)."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_io  # noqa: E402
import test_io_format13  # noqa: E402

sys.argv = [sys.argv[0]]
suite = unittest.TestSuite([unittest.defaultTestLoader.loadTestsFromModule(m) for m in (test_io, test_io_format13)])
r = unittest.TextTestRunner(verbosity=1).run(suite)
sys.exit(0 if r.wasSuccessful() else 1)
