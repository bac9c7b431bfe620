"""test_io.py, test_io_format13.py and test_io_format14.py run by Blender's Python, where numpy exists (the
vectorised geometry paths). Arguments after --: ZIP SPT WORKDIR (bl_common.args); SPT is what
test_io_format14.py packs with."""

import os
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bl_common  # noqa: E402

os.environ["SPT_TOOL"] = bl_common.args()[1]
import test_io  # noqa: E402
import test_io_format13  # noqa: E402
import test_io_format14  # noqa: E402

sys.argv = [sys.argv[0]]
modules = (test_io, test_io_format13, test_io_format14)
suite = unittest.TestSuite([unittest.defaultTestLoader.loadTestsFromModule(m) for m in modules])
r = unittest.TextTestRunner(verbosity=1).run(suite)
sys.exit(0 if r.wasSuccessful() else 1)
