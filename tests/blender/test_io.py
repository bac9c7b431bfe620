"""Unit tests of the add-on's bpy-free file layer (python3 -m unittest, no Blender needed): the
vectorised code the add-on ships against the one-tuple-per-stroke oracle in reference/."""

import os
import random
import struct
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import spt_samples  # noqa: E402  (puts blender_addon on sys.path)
from chunk_util import Tmp, damaged, fix_chunk_crc, read_all  # noqa: E402

import numpy as np  # noqa: E402
from reference import ref_geometry as geometry  # noqa: E402
from reference import ref_reader, ref_writer  # noqa: E402
from reference.ref_reader import apply_frames  # noqa: E402
from reference.ref_writer import frames_from_lists  # noqa: E402
from spt_grease_pencil.io import colors, state_np, stream_json, strokes_np  # noqa: E402
from spt_grease_pencil.io import geometry as geometry_np  # noqa: E402  (the vectorised one)
from spt_grease_pencil.io.model import AFFINE, CURVE, INTER, KEY, POLYGON, STAMP, Frame, SptError, NeedsPack  # noqa: E402
from spt_grease_pencil.io.reader import read_bytes, read_file  # noqa: E402
from spt_grease_pencil.io.writer import write_stored  # noqa: E402
from spt_grease_pencil.io.model import Limits  # noqa: E402


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


class RoundTrip(Tmp):
    def test_write_read_identical(self):
        inf, frames = spt_samples.animation(frames=5)
        p = self.path("a.spt")
        write_stored(p, inf, frames)
        f = ref_reader.read_file(p)
        self.assertTrue(f.complete)
        inf.header.frame_count = 5
        self.assertEqual(f.info.header, inf.header)
        self.assertEqual(f.info.templates, inf.templates)
        self.assertEqual(f.info.metadata, inf.metadata)
        self.assertEqual(len(f.frames), 5)
        for a, b in zip(f.frames, frames):
            self.assertEqual((a.index, a.type, a.removed, a.added), (b.index, b.type, b.removed, b.added))
            self.assertEqual(a.motion, b.motion)
        # Rewriting what was read gives the same bytes.
        p2 = self.path("b.spt")
        write_stored(p2, f.info, f.frames)
        self.assertEqual(read_all(p), read_all(p2))

    def test_polygons_read_write_identical_and_move_rigidly(self):
        """Format 1.2 polygon strokes (kind 3): the golden stored file reads back and writes
        byte-identically, and motion moves a polygon by its first vertex's block."""
        golden = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "format", "golden",
                              "polygons.stored.spt")
        f = read_file(golden)
        self.assertEqual(f.info.header.version_minor, 2)
        live = list(f.live_lists())
        self.assertTrue(any(st[0] == 3 for st in live[0]))
        out = self.path("poly.spt")
        write_stored(out, f.info, f.frames)
        self.assertEqual(read_all(out), read_all(golden))
        # Frame 1's motion: the 20-gon's first vertex (16*20 + 8*15, 16*18) = (440, 288) lies in
        # block (0, 0) of 32 px blocks, vector (-24, 8): every vertex moves by it.
        before = [st for st in live[0] if st[0] == 3][0]
        after = [st for st in live[1] if st[0] == 3][0]
        self.assertEqual(after[6], tuple((x - 24, y + 8) for (x, y) in before[6]))

    def test_state_update_remove_move_add(self):
        inf, frames = spt_samples.animation(frames=2, per_set=(2, 0, 0), affines=0, curves=0, motion=True)
        lists = list(apply_frames(inf.header, frames, Limits()))
        f1 = frames[1]
        kept = [s for i, s in enumerate(lists[0]) if i not in set(f1.removed)]
        self.assertEqual(len(lists[1]), len(kept) + len(f1.added))
        self.assertEqual(lists[1][len(kept):], f1.added)
        m = f1.motion
        for before, after in zip(kept, lists[1]):
            bx = min(max(before[4] // (16 * m.block_size), 0), m.cols - 1)
            by = min(max(before[5] // (16 * m.block_size), 0), m.rows - 1)
            dx, dy = m.vectors[by * m.cols + bx]
            self.assertEqual((after[4], after[5]), (before[4] + dx, before[5] + dy))

    def test_frames_from_lists_reproduces_lists(self):
        inf, frames = spt_samples.animation(frames=6)
        lists = list(apply_frames(inf.header, frames, Limits()))
        # Without motion most strokes persist: the coder must use inter frames.
        inf2, frames2 = spt_samples.animation(frames=6, motion=False)
        lists2 = list(apply_frames(inf2.header, frames2, Limits()))
        for ls in (lists, lists2):
            coded = frames_from_lists(ls)
            self.assertEqual(list(apply_frames(inf.header, coded, Limits())), ls)
        coded2 = frames_from_lists(lists2)
        self.assertTrue(all(fr.type == INTER for fr in coded2[1:]))
        self.assertEqual(coded2[0].type, KEY)


class Colors(unittest.TestCase):
    def test_all_codes_round_trip_through_float32(self):
        for k in range(256):
            self.assertEqual(colors.to_code(f32(colors.to_linear(k))), k)

    def test_edited_colours_round_to_nearest(self):
        self.assertEqual(colors.to_code(0.0), 0)
        self.assertEqual(colors.to_code(1.0), 255)
        self.assertEqual(colors.to_code(2.0), 255)
        self.assertEqual(colors.to_code(-1.0), 0)
        self.assertEqual(colors.to_code(colors.srgb_to_linear(0.5)), round(0.5 * 255))

    def test_numpy_bounds_agree(self):
        b = np.array(colors.BOUNDS)
        lin = np.array([f32(colors.to_linear(k)) for k in range(256)], dtype=np.float32)
        self.assertEqual(np.searchsorted(b, lin.astype(np.float64), side="right").tolist(), list(range(256)))


def through_blender_floats(corners):
    """What Grease Pencil stores: metres in float32, read back and scaled to pixels."""
    return [(f32(x / 1000.0) * 1000.0, f32(y / 1000.0) * 1000.0) for (x, y) in corners]


class Geometry(unittest.TestCase):
    def setUp(self):
        self.inf = spt_samples.info(width=4000, height=3000, sets=((64, 32), (32, 16), (32, 16), (5, 3)))
        self.h = self.inf.header
        self.rng = random.Random(3)

    def test_stamps_and_affines_survive_float32_metres(self):
        for _ in range(3000):
            s = spt_samples.random_stamp(self.rng, self.inf) if self.rng.random() < 0.7 else \
                spt_samples.random_affine(self.rng, self.inf)
            q = through_blender_floats(geometry.quad_corners(s, self.h.sets, self.h.orientations))
            hint = s[1] if s[0] == STAMP else None
            tmpl = s[2] if s[0] == STAMP else s[1]
            got = geometry.quad_to_stroke(q, tmpl, s[-4:], self.h.sets, self.h.orientations, hint)
            if s[0] == AFFINE and got[0] == STAMP:
                continue  # an affine stroke that happens to be a stamp: same pixels
            self.assertEqual(got, s)

    def test_moved_and_rotated(self):
        s = (STAMP, 0, 1, 2, 1600, 800, 1, 2, 3, 255)
        q = geometry.quad_corners(s, self.h.sets, self.h.orientations)
        moved = [(x + 10.25, y - 3.5) for x, y in q]
        got = geometry.quad_to_stroke(moved, 1, (1, 2, 3, 255), self.h.sets, self.h.orientations, 0)
        self.assertEqual(got, (STAMP, 0, 1, 2, 1600 + 164, 800 - 56, 1, 2, 3, 255))
        # Rotating by a table step (22.5 degrees) stays a stamp, with the next orientation.
        cx, cy = 100.0, 50.0
        import math
        t = math.pi / 8
        rot = [(cx + (x - cx) * math.cos(t) - (y - cy) * math.sin(t), cy + (x - cx) * math.sin(t) + (y - cy) * math.cos(t))
               for x, y in q]
        got = geometry.quad_to_stroke(rot, 1, (1, 2, 3, 255), self.h.sets, self.h.orientations, 0)
        self.assertEqual(got[:4], (STAMP, 0, 1, 3))
        # Any other angle makes it an affine stroke.
        t = 0.3
        rot = [(cx + (x - cx) * math.cos(t) - (y - cy) * math.sin(t), cy + (x - cx) * math.sin(t) + (y - cy) * math.cos(t))
               for x, y in q]
        got = geometry.quad_to_stroke(rot, 1, (1, 2, 3, 255), self.h.sets, self.h.orientations, 0)
        self.assertEqual(got[0], AFFINE)
        self.assertAlmostEqual(math.hypot(got[4], got[6]) / 16.0, 32.0, delta=0.1)

    def test_set_hint_picks_among_equal_sizes(self):
        for hint in (1, 2):
            s = (STAMP, hint, 0, 5, 800, 800, 9, 9, 9, 255)
            q = through_blender_floats(geometry.quad_corners(s, self.h.sets, self.h.orientations))
            self.assertEqual(geometry.quad_to_stroke(q, 0, (9, 9, 9, 255), self.h.sets, self.h.orientations, hint), s)

    def test_degenerate_quad_is_rejected(self):
        q = [(1.0, 1.0)] * 4
        self.assertIsNone(geometry.quad_to_stroke(q, 0, (0, 0, 0, 255), self.h.sets, self.h.orientations))

    def test_curve_points(self):
        s = (CURVE, 1, 2, 3, 200, ((16, 32, 40), (-160, 320, 8)))
        pts = [(f32(x / 1000.0) * 1000.0, f32(y / 1000.0) * 1000.0, f32(w)) for x, y, w in geometry.curve_points(s)]
        self.assertEqual(geometry.points_to_curve(pts, (1, 2, 3, 200)), s)

    def test_numpy_agrees_with_reference(self):
        strokes = [spt_samples.random_stamp(self.rng, self.inf) if i % 3 else spt_samples.random_affine(self.rng, self.inf)
                   for i in range(2000)]
        st = [s for s in strokes if s[0] == STAMP]
        af = [s for s in strokes if s[0] == AFFINE]
        cs = geometry_np.stamps_to_corners(np.array(st), self.h.sets, self.h.orientations)
        ca = geometry_np.affines_to_corners(np.array(af))
        for s, c in zip(st, cs):
            np.testing.assert_allclose(c, geometry.quad_corners(s, self.h.sets, self.h.orientations), atol=1e-9)
        for s, c in zip(af, ca):
            np.testing.assert_allclose(c, geometry.quad_corners(s, self.h.sets, self.h.orientations), atol=1e-9)
        allc = np.concatenate([cs, ca]).astype(np.float32).astype(np.float64)
        allc += np.random.default_rng(1).normal(0, 0.01, allc.shape) * (np.arange(len(allc)) % 5 == 0)[:, None, None]
        tm = [s[2] for s in st] + [s[1] for s in af]
        col = [s[-4:] for s in st + af]
        hint = [s[1] for s in st] + [0] * len(af)
        got = geometry_np.quads_to_strokes(allc, tm, col, self.h.sets, self.h.orientations, hint)
        ref = [geometry.quad_to_stroke([tuple(p) for p in c.tolist()], t, cc, self.h.sets, self.h.orientations, hh)
               for c, t, cc, hh in zip(allc, tm, col, hint)]
        self.assertEqual(got, ref)


class BadFiles(Tmp):
    def setUp(self):
        super().setUp()
        inf, frames = spt_samples.animation(frames=3)
        self.p = self.path("a.spt")
        write_stored(self.p, inf, frames)
        self.data = read_all(self.p)

    def test_signature(self):
        with self.assertRaisesRegex(SptError, "signature"):
            read_bytes(b"GIF89a" + self.data[6:], "x.spt")

    def test_flipped_byte_in_a_frame_stops_at_that_frame(self):
        d = bytearray(self.data)
        d[len(d) // 2] ^= 0x40
        f = read_bytes(bytes(d), "x.spt")  # recovery: the frames before the damage
        self.assertFalse(f.complete)
        self.assertIn("CRC", f.problem)
        self.assertLess(len(f.frames), 3)

    def test_truncated(self):
        for cut in (9, 30, len(self.data) // 2, len(self.data) - 5):
            try:
                f = read_bytes(self.data[:cut], "x.spt")
            except SptError as e:
                self.assertIn("x.spt", str(e))
                continue
            self.assertFalse(f.complete)

    def test_range_coded_frame_asks_for_pack(self):
        d = bytearray(self.data)
        # Find the first FRAM chunk, set its coding to 1 and fix the CRC.
        i = d.find(b"FRAM") - 4
        d[i + 8 + 5] = 1
        fix_chunk_crc(d, i)
        with self.assertRaises(NeedsPack):
            read_bytes(bytes(d), "x.spt")

    def test_random_corruption_never_crashes(self):
        rng = random.Random(5)
        for _ in range(300):
            d = damaged(self.data, rng)  # CRCs fixed, so the payload parsers see the damage
            try:
                f = read_bytes(bytes(d), "x.spt")
                for _l in f.live_lists():
                    pass
            except SptError:
                pass


class Columnar(Tmp):
    """The numpy fast path (strokes_np, state_np) against the tuple reference, same files."""

    def sample(self, **kw):
        inf, frames = spt_samples.animation(**kw)
        p = self.path("c.spt")
        write_stored(p, inf, frames)
        return p

    def test_live_lists_agree(self):
        for kw in ({"frames": 6}, {"frames": 5, "motion": False}, {"frames": 3, "curves": 0, "affines": 0},
                   {"frames": 6, "polygons": 4}, {"frames": 4, "polygons": 2, "motion": False},
                   {"frames": 5, "polygons": 2, "curves": 5, "curve_grids": True}):
            p = self.sample(**kw)
            ref = list(ref_reader.read_file(p).live_lists())
            f = read_file(p, columnar=True)
            got = [t.to_tuples() for t in f.live_lists()]
            self.assertEqual(got, ref)

    def test_rewrite_is_byte_identical(self):
        for polygons in (0, 4):
            p = self.sample(frames=6, polygons=polygons)
            f = read_file(p, columnar=True)
            p2 = self.path("c2.spt")
            write_stored(p2, f.info, f.frames)
            self.assertEqual(read_all(p), read_all(p2))
            self.assertEqual(read_file(p2).info.header.version_minor, 2 if polygons else 0)

    def test_polygon_rows(self):
        """Polygons in a StrokeTable: outline relative to P0 in the pool, X Y = P0, so moving one
        changes X Y only (rigid, by P0's block) and keeps its pool entry."""
        poly = (POLYGON, 1, 2, 3, 128, 4, ((160, 320), (480, 320), (300, 600), (-20, 500)))
        curves = []
        t = strokes_np.StrokeTable.from_tuples([poly], curves)
        r = t.rows[0]
        self.assertEqual((r[strokes_np.X], r[strokes_np.Y], r[strokes_np.GRID]), (160, 320, 4))
        self.assertEqual(curves[0].tolist(), [[0, 0], [320, 0], [140, 280], [-180, 180]])
        self.assertEqual(t.to_tuples(), [poly])
        inf = spt_samples.info()
        m = spt_samples.Motion(32, 5, 4, [(0, 0)] * 20)
        m.vectors[0] = (-24, 8)  # block (0, 0) holds P0 (10, 20) px; vertex 3 lies in no other block's way
        m.vectors[1] = (99, 99)  # block (1, 0) holds vertex 1 (30 px): must not matter
        frames = [Frame(0, KEY, added=t), Frame(1, INTER, removed=np.zeros(0, np.uint32), motion=m,
                                                added=strokes_np.StrokeTable(None, curves))]
        back = [x.to_tuples() for x in state_np.apply_frames(inf.header, frames, Limits(), curves=curves)]
        self.assertEqual(back[1], [poly[:6] + (tuple((x - 24, y + 8) for x, y in poly[6]),)])
        self.assertEqual(len(curves), 1, "a rigid move needs no new pool entry")
        # A move that takes a vertex (not P0) out of range is rejected, as by the reference.
        far = (POLYGON, 1, 2, 3, 255, 0, ((16, 16), (10 - (1 << 24), 16), (16, 400)))
        frames[0] = Frame(0, KEY, added=strokes_np.StrokeTable.from_tuples([far], curves))
        with self.assertRaises(SptError):
            list(state_np.apply_frames(inf.header, frames, Limits(), curves=curves))
        with self.assertRaises(SptError):
            list(apply_frames(inf.header, [Frame(0, KEY, added=[far]), Frame(1, INTER, motion=m)], Limits()))

    def test_frame_coding_agrees_with_reference(self):
        for motion, polygons in ((True, 0), (False, 0), (True, 3), (False, 3)):
            p = self.sample(frames=6, motion=motion, polygons=polygons)
            ref_lists = list(ref_reader.read_file(p).live_lists())
            f = read_file(p, columnar=True)
            tables = list(f.live_lists())
            got = state_np.frames_from_tables(tables, f.curves)
            want = frames_from_lists(ref_lists)
            a, b = self.path("a.spt"), self.path("b.spt")
            write_stored(a, f.info, got)
            write_stored(b, f.info, want)
            self.assertEqual(read_all(a), read_all(b))
            if not motion:
                self.assertTrue(all(fr.type == INTER for fr in got[1:]))

    def test_motion_fields_are_found_again(self):
        # The painter's inter frames move every stroke with a block field; the exporter's coder
        # must find such fields again (here: strokes of few kinds and colours, so many share
        # everything but their position, and with copies removed between frames).
        inf = spt_samples.info()
        rng = random.Random(4)
        h = inf.header
        cur = [(STAMP, rng.randrange(2), 0, rng.randrange(2), rng.randrange(16 * h.width), rng.randrange(16 * h.height),
                rng.choice((10, 200)), 5, 5, 255) for _ in range(120)]
        frames = [Frame(0, KEY, added=cur)]
        bs = 32
        cols, rows = -(-h.width // bs), -(-h.height // bs)
        for fi in range(1, 5):
            mv = spt_samples.Motion(bs, cols, rows, [(rng.randrange(-30, 31), rng.randrange(-30, 31)) for _ in range(cols * rows)])
            removed = sorted(rng.sample(range(120), 6))
            added = [(STAMP, 1, 1, 1, rng.randrange(16 * h.width), rng.randrange(16 * h.height), 10, 5, 5, 255) for _ in range(6)]
            frames.append(Frame(fi, INTER, removed=removed, motion=mv, added=added))
        p = self.path("m.spt")
        write_stored(p, inf, frames)
        f = read_file(p, columnar=True)
        tables = list(f.live_lists())
        # The block size seen on import is tried first (a 16 px field could express it too).
        got = state_np.frames_from_tables(tables, f.curves, h.width, h.height, [32, 16])
        self.assertTrue(all(fr.type == INTER and fr.motion is not None and fr.motion.block_size == 32 for fr in got[1:]))
        self.assertEqual([len(fr.removed) for fr in got[1:]], [6] * 4)
        back = list(state_np.apply_frames(h, got, Limits(), curves=f.curves))
        self.assertEqual([t.to_tuples() for t in back], [t.to_tuples() for t in tables])
        # Without block sizes: plain key/inter coding, still exact.
        plain = state_np.frames_from_tables(tables, f.curves)
        self.assertTrue(all(fr.motion is None for fr in plain))
        back = list(state_np.apply_frames(h, plain, Limits(), curves=f.curves))
        self.assertEqual([t.to_tuples() for t in back], [t.to_tuples() for t in tables])

    def test_polygon_motion_is_found_again(self):
        # Polygons moved by the painter's block field (rigidly, by P0's block) are coded with the
        # field again, not re-sent.
        inf = spt_samples.info()
        rng = random.Random(5)
        h = inf.header
        key = [spt_samples.random_polygon(rng, inf) for _ in range(30)] + \
              [spt_samples.random_stamp(rng, inf) for _ in range(30)]
        frames = [Frame(0, KEY, added=key)]
        cols, rows = -(-h.width // 32), -(-h.height // 32)
        for fi in range(1, 5):
            mv = spt_samples.Motion(32, cols, rows, [(rng.randrange(-30, 31), rng.randrange(-30, 31))
                                                     for _ in range(cols * rows)])
            added = [spt_samples.random_polygon(rng, inf) for _ in range(2)]
            frames.append(Frame(fi, INTER, removed=sorted(rng.sample(range(55), 3)), motion=mv, added=added))
        p = self.path("pm.spt")
        write_stored(p, inf, frames)
        f = read_file(p, columnar=True)
        h = f.info.header
        tables = list(f.live_lists())
        got = state_np.frames_from_tables(tables, f.curves, h.width, h.height, [32])
        self.assertTrue(all(fr.type == INTER and fr.motion is not None for fr in got[1:]))
        self.assertTrue(any(st[0] == POLYGON for st in tables[-1].to_tuples()))
        for fr, orig in zip(got[1:], f.frames[1:]):
            self.assertEqual(len(fr.added), len(orig.added), "only the new strokes are sent")
        back = list(state_np.apply_frames(h, got, Limits(), curves=f.curves))
        self.assertEqual([t.to_tuples() for t in back], [t.to_tuples() for t in tables])

    def test_duplicate_strokes_still_exact(self):
        inf = spt_samples.info()
        s1 = (STAMP, 0, 0, 0, 16, 16, 1, 2, 3, 255)
        s2 = (STAMP, 1, 0, 0, 32, 16, 1, 2, 3, 255)
        lists = [[s1, s2, s1, s1, s2], [s1, s1, s2, s1], [s2, s1, s2, s2, s1, s1], []]
        curves = []
        tables = [strokes_np.StrokeTable.from_tuples(l, curves) for l in lists]
        frames = state_np.frames_from_tables(tables, curves)
        p = self.path("d.spt")
        write_stored(p, inf, frames)
        self.assertEqual(list(read_file(p).live_lists()), lists)

    def test_corruption_gives_the_same_verdict(self):
        rng = random.Random(11)
        samples = [read_all(self.sample(frames=3, polygons=3)),
                   read_all(self.sample(frames=3, polygons=3, curve_grids=True))]  # format 1.4
        for k in range(400):
            d = damaged(samples[k % 2], rng)
            outcome = []
            for read in (ref_reader.read_bytes, lambda b, n: read_bytes(b, n, columnar=True)):
                try:
                    ls = list(read(bytes(d), "x.spt").live_lists())
                    outcome.append([t.to_tuples() if hasattr(t, "to_tuples") else t for t in ls])
                except SptError:
                    outcome.append("error")
            self.assertEqual(outcome[0], outcome[1])


class RecordBytes(unittest.TestCase):
    def test_packing_agrees_with_the_oracle(self):
        for kw in ({"frames": 3}, {"frames": 3, "polygons": 4}, {"frames": 3, "curves": 6, "curve_grids": True}):
            inf, frames = spt_samples.animation(**kw)
            g = inf.header.curve_grid
            for ls in apply_frames(inf.header, frames, Limits()):
                self.assertEqual(strokes_np.StrokeTable.from_tuples(ls).record_bytes(False, g),
                                 ref_writer.strokes_bytes(ls, False, g))

    def test_add_on_frame_coder_agrees_with_the_oracle(self):
        from spt_grease_pencil.io.writer import frames_from_lists as coder
        inf, frames = spt_samples.animation(frames=6, motion=False)
        lists = list(apply_frames(inf.header, frames, Limits()))
        got, want = coder(lists), frames_from_lists(lists)
        self.assertEqual([(f.type, list(f.removed), f.added.to_tuples() if hasattr(f.added, "to_tuples") else f.added)
                          for f in got],
                         [(f.type, list(f.removed), list(f.added)) for f in want])


class StreamJson(unittest.TestCase):
    def test_round_trip(self):
        inf = spt_samples.info()
        self.assertEqual(stream_json.from_json(stream_json.to_json(inf)), inf)


if __name__ == "__main__":
    unittest.main()
