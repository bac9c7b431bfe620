"""Picks the Grease Pencil backend for the running Blender (see gp_v2.py)."""

import bpy

if bpy.app.version >= (4, 3, 0):
    raise ImportError("spt Grease Pencil: Blender 4.3+ (Grease Pencil v3) is not supported yet; "
                      "use Blender 3.x-4.2")
from .gp_v2 import *  # noqa: F401,F403,E402
from . import gp_v2 as backend  # noqa: F401,E402
