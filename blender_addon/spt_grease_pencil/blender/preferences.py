"""Add-on preferences: where the `spt` executable is."""

import bpy
from bpy.props import StringProperty

from .. import spt_tool

# The add-on's own module: spt_grease_pencil as a legacy add-on, bl_ext.REPO.spt_grease_pencil as an
# extension (Blender 4.2+).
PACKAGE = __package__.rsplit(".", 1)[0]


def spt_path(context=None) -> str:
    """The configured path, or '' (meaning: next to the add-on or on PATH)."""
    ctx = context or bpy.context
    addon = ctx.preferences.addons.get(PACKAGE)
    return addon.preferences.spt_path if addon else ""


class SPT_AddonPreferences(bpy.types.AddonPreferences):
    bl_idname = PACKAGE

    spt_path: StringProperty(
        name="spt executable",
        description="Path to the spt tool. Empty: the spt next to the add-on, else the one on PATH",
        subtype='FILE_PATH', default="")

    def draw(self, context):
        layout = self.layout
        layout.prop(self, "spt_path")
        try:
            exe = spt_tool.resolve(self.spt_path)
            v = spt_tool.version(self.spt_path)
            layout.label(text=f"Using {exe} (version {'.'.join(map(str, v))})", icon='CHECKMARK')
        except spt_tool.SptToolError as e:
            layout.label(text=str(e), icon='ERROR')


classes = (SPT_AddonPreferences,)
