"""spt Grease Pencil: import, export and paint stroke animations (.spt) in Blender.

Layout as in glTF-Blender-IO: `io/` is the bpy-free file layer (plain Python, unit-testable
without Blender), `blender/` the Blender layer. bpy is imported only on register()."""

bl_info = {
    "name": "spt Grease Pencil",
    "author": "spt project",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import/Export > Stroke animation (.spt); Properties > Output > Paint to Strokes",
    "description": "Painterly stroke animations (.spt) as Grease Pencil: import, export, paint with spt",
    "category": "Import-Export",
}


def register():
    from . import blender
    blender.register()


def unregister():
    from . import blender
    blender.unregister()
