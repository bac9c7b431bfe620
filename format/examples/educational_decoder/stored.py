"""Stored frame bodies, coding 0 (SPEC.md 6)."""
from .errors import ByteReader, fail
from .strokes import AFFINE, CURVE, POLYGON, STAMP, Affine, Curve, Motion, Polygon, Stamp


def read_colour(r, linear):
    """u8 r, g, b, a; in colour encoding 1 then u8 r_lo, g_lo, b_lo (SPEC.md 6)."""
    rgba = tuple(r.take(4, "colour"))
    return rgba, tuple(r.take(3, "colour low bytes")) if linear else (0, 0, 0)


def read_record(r, linear, curve_grid):
    kind = r.u8("stroke kind")
    if kind == STAMP:
        set_, template, orient = r.u8("set"), r.u8("template"), r.u8("orient")
        x, y = r.i32("x"), r.i32("y")
        rgba, lo = read_colour(r, linear)
        return Stamp(set_, template, orient, x, y, rgba, lo=lo)
    if kind == AFFINE:
        template = r.u8("template")
        tx, ty, a, b, c, d = (r.i32(name) for name in ("tx", "ty", "a", "b", "c", "d"))
        rgba, lo = read_colour(r, linear)
        return Affine(template, tx, ty, a, b, c, d, rgba, lo=lo)
    if kind == CURVE:
        rgba, lo = read_colour(r, linear)
        grid = r.u8("grid") if curve_grid else 0  # format 1.4: only with the HEAD flag
        n = r.u32("point count")
        if n * 12 > r.left():
            fail("Truncated", f"{r.what}: curve of {n} points does not fit the body")
        return Curve(rgba, [[r.i32("x"), r.i32("y"), r.u32("width")] for _ in range(n)], lo=lo, grid=grid)
    if kind == POLYGON:  # kind 3 decodes in coding 0 whatever version_minor says (SPEC.md 6)
        rgba, lo = read_colour(r, linear)
        grid = r.u8("grid")
        n = r.u32("vertex count")
        if n * 8 > r.left():
            fail("Truncated", f"{r.what}: polygon of {n} vertices does not fit the body")
        return Polygon(rgba, grid, [[r.i32("x"), r.i32("y")] for _ in range(n)], lo=lo)
    fail("Unsupported", f"{r.what}: stroke kind {kind} is reserved")


def read_records(r, count, linear, curve_grid):
    if count * 16 > r.left():
        fail("Corrupt", f"{r.what}: {count} strokes cannot fit the body")
    return [read_record(r, linear, curve_grid) for _ in range(count)]


def decode_stored(body, key, header, what):
    """Returns (removed, motion, added) of a coding-0 body."""
    r = ByteReader(body, what)
    removed, motion = [], None
    if not key:
        count = r.u32("removed_count")
        if count * 4 > r.left():
            fail("Corrupt", f"{what}: {count} removals cannot fit the body")
        removed = [r.u32("removed") for _ in range(count)]
        if any(b <= a for a, b in zip(removed, removed[1:])):
            fail("Corrupt", f"{what}: removals are not strictly increasing")
        present = r.u8("motion_present")
        if present > 1:
            fail("Unsupported", f"{what}: motion_present {present} is reserved")
        if present:
            bs, cols, rows = r.u16("block_size"), r.u16("cols"), r.u16("rows")
            if not 8 <= bs <= 256:
                fail("Corrupt", f"{what}: motion block size {bs} outside 8..256")
            if cols != -(-header.width // bs) or rows != -(-header.height // bs):
                fail("Corrupt", f"{what}: motion field is not the canvas's cols x rows")
            if cols * rows * 4 > r.left():
                fail("Corrupt", f"{what}: motion field cannot fit the body")
            motion = Motion(bs, cols, rows, [(r.i16("dx"), r.i16("dy")) for _ in range(cols * rows)])
    added = read_records(r, r.u32("stroke_count" if key else "added_count"), header.color_encoding == 1,
                         header.curve_grid)
    r.end()
    return removed, motion, added
