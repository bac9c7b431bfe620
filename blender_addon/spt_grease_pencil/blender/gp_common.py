"""The Grease Pencil calls that are the same in both data models (GPv2 and GPv3): the camera,
the template stencils and the materials (MaterialGPencilStyle did not change in 4.3), and the
frame lookup. The backends (gp_v2.py, gp_v3.py) re-export these.

Units: 1 px = 1 mm. Point coordinates are metres in the object's XZ plane: x_px / 1000 -> X,
y_px / 1000 -> -Z (image y grows downward). The object is not scaled, so brush sizes behave as
usual when an artist draws.
"""

import bisect

import bpy
import numpy as np


def new_camera(context, name: str, width: int, height: int):
    """An orthographic camera that frames the W x H mm canvas exactly."""
    cam = bpy.data.cameras.new(name)
    cam.type = 'ORTHO'
    cam.ortho_scale = max(width, height) / 1000.0
    cam.sensor_fit = 'AUTO'
    obj = bpy.data.objects.new(name, cam)
    obj.location = (width / 2000.0, -1.0, -height / 2000.0)
    obj.rotation_euler = (np.pi / 2, 0.0, 0.0)
    context.scene.collection.objects.link(obj)
    return obj


def stencil_image(name: str, coverage: np.ndarray):
    """An image whose alpha is the template coverage (rows top first, 0..255), rgb white."""
    h, w = coverage.shape
    img = bpy.data.images.new(name, width=w, height=h, alpha=True)
    px = np.ones((h, w, 4), dtype=np.float32)
    px[:, :, 3] = coverage[::-1, :].astype(np.float32) / 255.0  # Blender rows are bottom first
    img.pixels.foreach_set(px.ravel())
    img.pack()
    return img


def _gp_material(name: str, stroke: bool, fill: bool):
    """A Grease Pencil material that shows its line, its fill or both. Blender 5.x also decides
    this per stroke (gp_v3.fill_frame writes fill_id and hide_stroke to agree)."""
    mat = bpy.data.materials.new(name)
    bpy.data.materials.create_gpencil_data(mat)
    gp = mat.grease_pencil
    gp.show_stroke = stroke
    gp.show_fill = fill
    return mat, gp


def template_material(name: str, image):
    mat, gp = _gp_material(name, stroke=False, fill=True)
    gp.fill_style = 'TEXTURE'
    gp.fill_image = image
    gp.mix_factor = 1.0
    gp.texture_clamp = True
    gp.texture_offset = (-0.5, -0.5)
    gp.fill_color = (1.0, 1.0, 1.0, 1.0)
    return mat


def curve_material(name: str):
    mat, gp = _gp_material(name, stroke=True, fill=False)
    gp.color = (1.0, 1.0, 1.0, 1.0)
    return mat


def polygon_material(name: str, alpha: int):
    """Solid fill, no line: white with the polygons' alpha, tinted per stroke by the fill colour
    (mix 1), so vertex paint recolours a polygon as it does a quad."""
    mat, gp = _gp_material(name, stroke=False, fill=True)
    gp.fill_style = 'SOLID'
    gp.fill_color = (1.0, 1.0, 1.0, alpha / 255.0)
    return mat


def add_material(obj, mat) -> int:
    obj.data.materials.append(mat)
    return len(obj.data.materials) - 1


def material_color(mat, fill: bool):
    if mat is None or mat.grease_pencil is None:
        return (0.0, 0.0, 0.0, 1.0)
    gp = mat.grease_pencil
    return tuple(gp.fill_color if fill else gp.color)


def frame_at_sorted(index, number: int):
    """The frame shown at scene frame `number` (the latest key at or before it) or None; index is
    a backend's frame_index(layer): (sorted frame numbers, frames)."""
    numbers, frs = index
    k = bisect.bisect_right(numbers, number) - 1
    return frs[k] if k >= 0 else None


def frame_index(layer):
    """(sorted frame numbers, frames) of a layer, for frame_at_sorted."""
    frs = sorted(layer.frames, key=lambda f: f.frame_number)
    return [f.frame_number for f in frs], frs


_MADE_BY_IMPORT = ("objects", "materials", "images", "cameras", "worlds")


def snapshot():
    """The data-blocks that exist now, for remove_since: an import that fails half-way removes
    what it made, so nothing half-made is left in the file."""
    return {c: set(getattr(bpy.data, c)[:]) for c in _MADE_BY_IMPORT}


def remove_since(snap):
    for c in _MADE_BY_IMPORT:
        coll = getattr(bpy.data, c)
        for idb in [x for x in coll if x not in snap[c]]:
            data = getattr(idb, "data", None) if c == "objects" else None
            coll.remove(idb)
            if data is not None and data.users == 0:
                for dc in ("grease_pencils_v3", "grease_pencils", "cameras"):
                    dcoll = getattr(bpy.data, dc, None)
                    if dcoll is not None and data in dcoll[:]:
                        dcoll.remove(data)
                        break
