"""test_io.py run by Blender's Python, where numpy exists (the vectorised geometry paths)."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import test_io  # noqa: E402

sys.argv = [sys.argv[0]]
r = unittest.TextTestRunner(verbosity=1).run(unittest.defaultTestLoader.loadTestsFromModule(test_io))
sys.exit(0 if r.wasSuccessful() else 1)
