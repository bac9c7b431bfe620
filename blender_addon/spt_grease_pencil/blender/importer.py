"""File > Import > Stroke animation (.spt): builds one Grease Pencil object from a file.

Layering 'SETS': one layer per stroke set, coarse (bottom) to fine (top), then "shapes" (affine and
polygon strokes, in their drawing order: shape painters overlap them) and "curves": an artist can
hide, lock or retouch the detail pass apart from the under-painting. 'KINDS' (flat-colour art, as
`spt paint --style cartoon` paints it): "fills" (polygons), "lines" (curves), "paint" (stamps and
affine strokes, the residual drawn over the fills). Per kind rather than per colour: a cartoon's
regions are drawn largest first whatever their colour, so colour layers would each need strokes
from below and above the others and the viewport would no longer match the file, while the kinds
follow the painter's order (fills, then the residual). 'AUTO' takes KINDS when a frame holds a
polygon, SETS otherwise. The file's exact drawing order is kept per stroke (its ordinal, see
gp_v2.py), so export restores it even though inter frames interleave layers. 'SINGLE' puts
everything in one layer, whose viewport order is then exactly the file's.
"""

import os
import time

import numpy as np

from ..io import colors, geometry, stream_json
from ..io.model import AFFINE, CURVE, POLYGON, STAMP, NeedsPack, SptError
from ..io.reader import read_file
from ..io.strokes_np import A, B, CURVE_ID, GRID, KIND, R, SET, TMPL, X, Y
from ..spt_tool import pack_stored, temp_path
from . import gp
from .stroke_batch import FILL, LINE, QUAD, StrokeBatch, point_index


def scene_linear(values, h):
    """A file's colour values as Grease Pencil's scene-linear float32: the sRGB table in colour
    encoding 0; in colour encoding 1 the half codes' own values, exactly (no conversion: GP
    colours are scene-linear already, and every half is a float32)."""
    return colors.values_to_linear(values, h.linear)


def load_stored(path: str, spt_path: str):
    """Reads `path`; a range-coded file goes through `spt pack --stored` first."""
    if not os.path.isfile(path):
        raise SptError(f"{path}: no such file")
    try:
        return read_file(path, columnar=True)
    except NeedsPack:
        pass
    tmp = temp_path()
    try:
        pack_stored(spt_path, path, tmp)
        f = read_file(tmp, columnar=True)
        f.path = path
        return f
    finally:
        try:
            os.unlink(tmp)
        except OSError:
            pass


def template_coverage(t, size: int = 128) -> np.ndarray:
    """(rows top first) coverage 0..255 of a template; analytic kinds sampled at pixel centres."""
    if t.kind == 0:
        return np.frombuffer(t.pixels, dtype=np.uint8).reshape(t.height, t.width)
    c = (np.arange(size) + 0.5) / size * 2.0 - 1.0
    u, v = np.meshgrid(c, c)  # v grows downward with the row
    if t.kind == 1:
        inside = u * u + v * v <= 1.0
    elif t.kind == 2:
        inside = np.ones_like(u, dtype=bool)
    else:
        inside = (u >= -1) & (v >= -1) & (u + v <= 0)
    return np.where(inside, 255, 0).astype(np.uint8)


BLENDER_MAX_FRAME = 1048574


def source_first_frame(info):
    """The source's number of frame 0 (SPEC 3.3, metadata source.first_frame: decimal, no sign), or
    None when the file has none or a malformed one, or when its frames would not fit Blender's
    frame range (then the clip starts at the scene's start frame, as files without the key do)."""
    for key, value in info.metadata:
        if key == "source.first_frame":
            if not value.isascii() or not value.isdigit() or int(value) > 0xFFFFFFFF:
                return None
            return int(value)
    return None


def _scene_setup(context, info, count, start):
    scene = context.scene
    h = info.header
    scene.render.resolution_x = h.width
    scene.render.resolution_y = h.height
    scene.render.resolution_percentage = 100
    fps = h.fps_num / h.fps_den
    scene.render.fps = max(1, min(32767, round(fps)))
    scene.render.fps_base = scene.render.fps / fps
    scene.frame_start = start
    scene.frame_end = start + max(count, 1) - 1
    world = scene.world
    if world is None:
        import bpy
        world = scene.world = bpy.data.worlds.new("spt background")
    rgb = tuple(float(c) for c in scene_linear(h.background_values(), h))
    world.color = rgb
    if h.alpha:
        # An alpha canvas: renders keep their transparency so they composite over a plate; the
        # world colour (the file's background) is only what the viewport shows behind it.
        scene.render.film_transparent = True
    # Blender 5.x always renders worlds through their nodes (world.color is the viewport's only).
    bg = world.node_tree.nodes.get("Background") if getattr(world, "node_tree", None) else None
    if bg is not None and getattr(world, "use_nodes", False):
        bg.inputs["Color"].default_value = rgb + (1.0,)


KIND_LAYERS = ("fills", "lines", "paint")  # bottom to top


def resolve_layering(layering, tables):
    """'AUTO' as KINDS when any frame holds a polygon (flat-colour art), else SETS."""
    if layering != 'AUTO':
        return layering
    return 'KINDS' if any((t.rows[:, KIND] == POLYGON).any() for t in tables) else 'SETS'


def _layer_keys(rows, layering, nsets):
    """Per stroke, the index of its layer key in the list ('set', i) * nsets + ['shapes', 'curves']
    (SETS), in KIND_LAYERS (KINDS) or 0 (SINGLE)."""
    if layering == 'SINGLE':
        return np.zeros(rows.shape[0], dtype=np.int64)
    kind = rows[:, KIND]
    if layering == 'KINDS':
        return np.where(kind == POLYGON, 0, np.where(kind == CURVE, 1, 2)).astype(np.int64)
    shapes = (kind == AFFINE) | (kind == POLYGON)
    return np.where(kind == STAMP, rows[:, SET], np.where(shapes, nsets, nsets + 1)).astype(np.int64)


def _polygon_key(rows):
    """Per row, alpha * 17 + grid N: the polygon material a polygon row uses."""
    return rows[:, A].astype(np.int64) * 17 + rows[:, GRID]


def polygon_materials(obj, name, tables):
    """One material per (alpha, grid N) the polygons use (gp_v2.py: a GP fill takes its alpha from
    the material only); returns the lookup array key (_polygon_key) -> material index."""
    keys = set()
    for t in tables:
        poly = t.rows[:, KIND] == POLYGON
        if poly.any():
            keys.update(np.unique(_polygon_key(t.rows[poly])).tolist())
    lookup = np.full(256 * 17, -1, dtype=np.int32)
    for k in sorted(keys):
        alpha, grid = divmod(k, 17)
        mat = gp.polygon_material(f"{name} polygon alpha {alpha} grid {grid}", alpha)
        mat["spt_polygon_grid"] = grid
        lookup[k] = gp.add_material(obj, mat)
    return lookup


def curve_materials(obj, name, tables):
    """The curve materials: "<name> curve" for grid 0 (every curve of a file before format 1.4,
    so those import as they always did) and one per other grid N the curves use (format 1.4),
    which carries it as spt_curve_grid for export. Returns the lookup array grid -> material
    index."""
    grids = {0}
    for t in tables:
        line = t.rows[:, KIND] == CURVE
        if line.any():
            grids.update(np.unique(t.rows[line, GRID]).tolist())
    lookup = np.full(17, -1, dtype=np.int32)
    for g in sorted(grids):
        mat = gp.curve_material(f"{name} curve" + (f" grid {g}" if g else ""))
        mat["spt_curve"] = 1
        if g:
            mat["spt_curve_grid"] = g
        lookup[g] = gp.add_material(obj, mat)
    return lookup


def import_file(context, path: str, spt_path: str = "", layering: str = 'AUTO', progress=None):
    """Returns (object, summary dict). Raises SptError / SptToolError with a readable message.
    summary["seconds"] splits the time: read (spt pack --stored + Python reader + live lists),
    build (Grease Pencil data)."""
    t0 = time.perf_counter()
    f = load_stored(path, spt_path)
    info = f.info
    h = info.header
    if not f.frames:
        raise SptError(f"{path}: the file holds no frames")
    tables = list(f.live_lists())  # StrokeTables; inter frames share nothing mutable
    layering = resolve_layering(layering, tables)
    t1 = time.perf_counter()
    made = gp.snapshot()
    try:
        obj, layer_of, total_strokes = _build(context, f, tables, path, layering, progress)
    except BaseException:
        gp.remove_since(made)  # nothing half-made stays in the scene
        raise
    summary = {"frames": len(tables), "strokes": total_strokes, "layers": len(layer_of), "layering": layering,
               "templates": len(info.templates), "complete": f.complete, "problem": f.problem,
               "seconds": {"read": t1 - t0, "build": time.perf_counter() - t1}}
    return obj, summary


def _build(context, f, tables, path, layering, progress):
    """The Grease Pencil object, its materials, layers and frames, the camera and the scene set-up;
    returns (object, layers, stroke count)."""
    info = f.info
    h = info.header
    name = os.path.splitext(os.path.basename(path))[0] or "strokes"
    obj = gp.new_object(context, name)

    tmat = []
    for ti, t in enumerate(info.templates):
        img = gp.stencil_image(f"{name} template {ti} {t.name}".strip(), template_coverage(t))
        mat = gp.template_material(f"{name} {t.name or 'template'} {ti}", img)
        mat["spt_template"] = ti
        tmat.append(gp.add_material(obj, mat))
    mat_of_curve = curve_materials(obj, name, tables)
    mat_of_tmpl = np.array(tmat + [mat_of_curve[0]], dtype=np.int32)
    mat_of_poly = polygon_materials(obj, name, tables)

    # Layers bottom to top: the stroke sets used (coarse to fine), shapes, curves; the kinds used;
    # or one layer.
    nsets = len(h.sets)
    used = np.zeros(nsets + 2, dtype=bool)
    for t in tables:
        used[np.unique(_layer_keys(t.rows, 'SETS', nsets))] = True
    if layering == 'SINGLE':
        layer_of = {0: gp.new_layer(obj, "strokes")}
    elif layering == 'KINDS':
        kinds = np.zeros(len(KIND_LAYERS), dtype=bool)
        for t in tables:
            kinds[np.unique(_layer_keys(t.rows, 'KINDS', nsets))] = True
        if not kinds.any():
            kinds[0] = True
        layer_of = {k: gp.new_layer(obj, KIND_LAYERS[k]) for k in np.flatnonzero(kinds).tolist()}
    else:
        if not used.any():
            used[nsets + 1] = True
        layer_of = {}
        for k in np.flatnonzero(used).tolist():
            label = f"set {k} ({h.sets[k][0]}x{h.sets[k][1]})" if k < nsets else ("shapes" if k == nsets else "curves")
            layer_of[k] = gp.new_layer(obj, label)

    # A clip painted from shot.1001.exr... lands on the scene's frames from 1001.
    start = source_first_frame(info)
    if start is None or start + len(tables) - 1 > BLENDER_MAX_FRAME:
        start = context.scene.frame_start
    total_strokes = 0
    for fi, table in enumerate(tables):
        _fill_frame(table, start + fi, layer_of, layering, h, mat_of_tmpl, mat_of_curve, mat_of_poly)
        total_strokes += len(table)
        if progress:
            progress(fi + 1, len(tables))

    gpd = obj.data
    gpd["spt_stream"] = stream_json.to_json(info)
    gpd["spt_frame_start"] = start
    gpd["spt_frame_count"] = len(tables)
    gpd["spt_source"] = path
    # Export tries these block sizes first to find the motion fields again (state_np.find_motion).
    gpd["spt_motion_blocks"] = sorted({fr.motion.block_size for fr in f.frames if fr.motion is not None})
    _scene_setup(context, info, len(tables), start)
    cam = gp.new_camera(context, f"{name} camera", h.width, h.height)
    context.scene.camera = cam
    return obj, layer_of, total_strokes


def _pool_points(table, idx, columns):
    """The pool entries of rows `idx` stacked: ((sum m, columns) int64, counts (len(idx),))."""
    pieces = [table.curves[c] for c in table.rows[idx, CURVE_ID].tolist()]
    counts = np.fromiter((p.shape[0] for p in pieces), dtype=np.int64, count=len(pieces))
    if not pieces:
        return np.zeros((0, columns), dtype=np.int64), counts
    return np.concatenate(pieces).astype(np.int64).reshape(-1, columns), counts


def frame_batch(table, idx, h, material, fill) -> StrokeBatch:
    """The strokes `idx` of a file frame (in drawing order) as one layer frame's StrokeBatch: quads
    (stamps and affine strokes) with their 4 corners, polygons with their outline in file order,
    curves with per-point width, opacity and colour; everything in metres (1 px = 1 mm)."""
    rows = table.rows[idx]
    n = rows.shape[0]
    kind = rows[:, KIND]
    is_curve = kind == CURVE
    is_poly = kind == POLYGON
    quad = ~(is_curve | is_poly)
    counts = np.full(n, 4, dtype=np.int64)
    pi, pcounts = _pool_points(table, idx[is_poly], 2)
    ci, ccounts = _pool_points(table, idx[is_curve], 3)
    counts[is_poly] = pcounts
    counts[is_curve] = ccounts
    off = np.zeros(n + 1, dtype=np.int64)
    np.cumsum(counts, out=off[1:])
    m = int(off[-1])
    xy = np.zeros((m, 2), dtype=np.float64)   # px
    width = np.zeros(m, dtype=np.float32)
    opacity = np.ones(m, dtype=np.float32)
    vcol = np.zeros((m, 4), dtype=np.float32)
    if quad.any():
        q = np.flatnonzero(quad)
        c = geometry.table_corners(rows[q], h.sets, h.orientations)
        xy[point_index(off[q], counts[q])] = c.reshape(-1, 2)
    if is_poly.any():
        p = np.flatnonzero(is_poly)
        first = np.repeat(rows[p][:, [X, Y]].astype(np.int64), pcounts, axis=0)
        xy[point_index(off[p], pcounts)] = (pi + first).astype(np.float64) / 16.0
    if is_curve.any():
        k = np.flatnonzero(is_curve)
        at = point_index(off[k], ccounts)
        xy[at] = ci[:, :2].astype(np.float64) / 16.0
        width[at] = ci[:, 2].astype(np.float64) / 16.0
        opacity[at] = np.repeat(rows[k, A].astype(np.float32) / 255.0, ccounts)
        vcol[at, 0:3] = np.repeat(scene_linear(rows[k, R:B + 1], h), ccounts, axis=0)
        vcol[at, 3] = 1.0
    co = np.zeros((m, 3), dtype=np.float32)
    co[:, 0] = xy[:, 0] / 1000.0
    co[:, 2] = -xy[:, 1] / 1000.0
    shape = np.where(quad, QUAD, np.where(is_curve, LINE, FILL)).astype(np.int8)
    return StrokeBatch(shape=shape, counts=counts, co=co, width=width, opacity=opacity, vcol=vcol,
                       material=material, fill=fill, ordinal=np.asarray(idx, dtype=np.int64),
                       set_hint=rows[:, SET].astype(np.int64), alpha=rows[:, A].astype(np.int64))


def _fill_frame(table, number, layer_of, layering, h, mat_of_tmpl, mat_of_curve, mat_of_poly):
    """One file frame: a GP frame on every layer (an empty one where the layer has nothing, so
    the previous frame does not stay visible), each with its strokes in drawing order."""
    rows = table.rows
    n = rows.shape[0]
    kind = rows[:, KIND]
    is_curve = kind == CURVE
    is_poly = kind == POLYGON
    quad = ~(is_curve | is_poly)
    fill = np.ones((n, 4), dtype=np.float32)
    fill[:, 0:3] = scene_linear(rows[:, R:B + 1], h)
    material = np.where(is_curve, mat_of_curve[np.where(is_curve, rows[:, GRID], 0)],
                        mat_of_tmpl[np.where(quad, rows[:, TMPL], 0)])
    material = np.where(is_poly, mat_of_poly[_polygon_key(rows) % mat_of_poly.shape[0]], material)
    keys = _layer_keys(rows, layering, len(h.sets))
    for k, layer in layer_of.items():
        frame = gp.new_frame(layer, number)
        idx = np.flatnonzero(keys == k)
        if idx.size:
            gp.fill_frame(frame, frame_batch(table, idx, h, material[idx].astype(np.int32), fill[idx]))
