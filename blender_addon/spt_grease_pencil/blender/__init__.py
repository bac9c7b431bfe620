"""The Blender layer: operators, panel and preferences (needs bpy)."""

import bpy

from . import operators, panel, preferences

_classes = preferences.classes + panel.classes + operators.classes


def register():
    for c in _classes:
        bpy.utils.register_class(c)
    bpy.types.Scene.spt_paint = bpy.props.PointerProperty(type=panel.SPT_PaintSettings)
    bpy.types.TOPBAR_MT_file_import.append(operators.menu_import)
    bpy.types.TOPBAR_MT_file_export.append(operators.menu_export)


def unregister():
    bpy.types.TOPBAR_MT_file_export.remove(operators.menu_export)
    bpy.types.TOPBAR_MT_file_import.remove(operators.menu_import)
    del bpy.types.Scene.spt_paint
    for c in reversed(_classes):
        bpy.utils.unregister_class(c)
