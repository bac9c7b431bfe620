"""Picks the Grease Pencil backend for the running Blender: gp_v2.py for the GPv2 data model
(Blender 3.x-4.2), gp_v3.py for GPv3 (4.3 and later, the only one in 5.x). Both offer the same
functions and constants; the importer and exporter call only these (`gp.fill_frame`, ...)."""

import bpy

if bpy.app.version >= (4, 3, 0):
    from .gp_v3 import *  # noqa: F401,F403
    from . import gp_v3 as backend  # noqa: F401
else:
    from .gp_v2 import *  # noqa: F401,F403
    from . import gp_v2 as backend  # noqa: F401
