"""Format 1.4 in the add-on's bpy-free file layer (python3 -m unittest, no Blender needed):
anti-aliased curves. A file with the HEAD flag curve_grid stores a supersampling grid N in every
curve record; the layer reads it (GRID column, model.py tuples), writes it back byte for byte,
agrees with the tuple oracle in reference/, and refuses reserved grids and HEAD flags.

The coded half of the round trip needs the real spt (`spt pack`): CTest names it in SPT_TOOL, and
a test that needs it fails when it is missing (it never passes by skipping)."""

import os
import struct
import subprocess
import sys
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import spt_samples  # noqa: E402  (puts blender_addon on sys.path)
from chunk_util import Tmp, fix_chunk_crc, read_all  # noqa: E402

from reference import ref_geometry, ref_reader, ref_writer  # noqa: E402
from spt_grease_pencil.io import geometry, stream_json, strokes_np  # noqa: E402
from spt_grease_pencil.io.model import CURVE, SptError, curve_grid_of  # noqa: E402
from spt_grease_pencil.io.reader import read_bytes, read_file  # noqa: E402
from spt_grease_pencil.io.writer import write_stored  # noqa: E402

GOLDEN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "format", "golden")
SPT = os.environ.get("SPT_TOOL", "")


def golden(name="curves_aa", stored=True):
    return os.path.join(GOLDEN, name + (".stored.spt" if stored else ".spt"))


def spt(*args):
    """Runs the real spt; fails the test (not skips) when there is none."""
    if not SPT or not os.access(SPT, os.X_OK):
        raise AssertionError(f"SPT_TOOL is '{SPT}': these tests need the built spt (CTest sets it)")
    r = subprocess.run([SPT, *args], capture_output=True, text=True)
    if r.returncode != 0:
        raise AssertionError(f"spt {' '.join(args)}: {r.stderr or r.stdout}")


def aa_sample(linear=False, frames=4):
    """A small animation of every kind whose curves carry grids 0, 2, 4 and 16 (moved by motion
    fields, removed, added), in colour encoding 0 or 1."""
    if linear:
        inf, fr = spt_samples.linear_animation(frames=frames, polygons=2, curves=6, curve_grids=True)
    else:
        inf, fr = spt_samples.animation(frames=frames, polygons=2, curves=6, curve_grids=True)
    return inf, fr


def first_curve_record(data: bytes):
    """(offset of frame 0's chunk, offset of its first curve record) in a stored file whose
    frame 0 is a key frame of the records strokes_np writes."""
    t = data.find(b"FRAM") - 4
    body = t + 8 + 8
    f = ref_reader.read_bytes(data, "x.spt")
    linear = f.info.header.linear
    pos = body + 4
    for s in f.frames[0].added:
        if s[0] == CURVE:
            return t, pos
        pos += len(ref_writer.strokes_bytes([s], linear, f.info.header.curve_grid))
    raise AssertionError("frame 0 holds no curve")


class GoldenFile(Tmp):
    """tests/format/golden/curves_aa(.stored).spt, written by libspt."""

    def test_header_and_grids(self):
        f = read_file(golden())
        h = f.info.header
        self.assertTrue(f.complete)
        self.assertEqual((h.curve_grid, h.version_minor), (True, 4))
        grids = {curve_grid_of(s) for ls in f.live_lists() for s in ls if s[0] == CURVE}
        self.assertIn(0, grids, "a curve sampled at pixel centres")
        self.assertTrue(grids - {0}, "anti-aliased curves")

    def test_rewrite_is_byte_identical(self):
        for columnar in (False, True):
            f = read_file(golden(), columnar=columnar)
            out = self.path("aa.spt")
            write_stored(out, f.info, f.frames)
            self.assertEqual(read_all(out), read_all(golden()), f"columnar={columnar}")

    def test_numpy_reader_and_packer_agree_with_the_oracle(self):
        ref = list(ref_reader.read_file(golden()).live_lists())
        got = [t.to_tuples() for t in read_file(golden(), columnar=True).live_lists()]
        self.assertEqual(got, ref)
        h = read_file(golden()).info.header
        for ls in ref:
            self.assertEqual(strokes_np.StrokeTable.from_tuples(ls).record_bytes(h.linear, True),
                             ref_writer.strokes_bytes(ls, h.linear, True))

    def test_coded_twin_packs_to_the_same_strokes(self):
        back = self.path("back.spt")
        spt("pack", golden(stored=False), "--stored", "-o", back)
        f = read_file(back)
        self.assertEqual((f.info.header.curve_grid, f.info.header.version_minor), (True, 4))
        self.assertEqual(list(f.live_lists()), list(read_file(golden()).live_lists()))

    def test_stream_json_keeps_the_flag(self):
        info = read_file(golden()).info
        self.assertTrue(stream_json.from_json(stream_json.to_json(info)).header.curve_grid)
        # JSON written before format 1.4 has no key: no flag
        info.header.curve_grid = False
        text = stream_json.to_json(info).replace(',"curve_grid":false', "")
        self.assertNotIn("curve_grid", text)
        self.assertFalse(stream_json.from_json(text).header.curve_grid)


class Written(Tmp):
    def test_round_trip_both_encodings(self):
        for linear in (False, True):
            inf, frames = aa_sample(linear)
            p = self.path("aa.spt")
            write_stored(p, inf, frames)
            f = read_file(p)
            self.assertEqual((f.info.header.curve_grid, f.info.header.version_minor), (True, 4))
            ref = list(ref_reader.read_file(p).live_lists())
            self.assertEqual(list(f.live_lists()), ref)
            self.assertEqual([t.to_tuples() for t in read_file(p, columnar=True).live_lists()], ref)
            self.assertEqual({curve_grid_of(s) for ls in ref for s in ls if s[0] == CURVE}, {0, 2, 4, 16})
            self.assertEqual(ref[0], frames[0].added, "frame 0 as written")
            for columnar in (False, True):
                g = read_file(p, columnar=columnar)
                p2 = self.path("aa2.spt")
                write_stored(p2, g.info, g.frames)
                self.assertEqual(read_all(p2), read_all(p), f"linear={linear} columnar={columnar}")

    def test_curve_records_carry_the_grid_byte(self):
        """One curve of grid 4, with and without colour encoding 1: the grid follows the colour
        (and its low bytes), as a polygon's does (SPEC.md 6)."""
        pts = ((100, 120, 32), (400, 90, 48))
        for linear, colour, lo in ((False, (10, 20, 30), b""), (True, (0x3C01, 0x2E66, 0x7BFF), b"\x01\x66\xff")):
            s = (CURVE,) + colour + (200, pts, 4)
            rec = strokes_np.StrokeTable.from_tuples([s]).record_bytes(linear, True)
            hi = bytes(c >> 8 for c in colour) if linear else bytes(colour)
            head = bytes([CURVE]) + hi + b"\xc8" + lo + b"\x04" + struct.pack("<I", 2)
            self.assertEqual(rec, head + b"".join(struct.pack("<iiI", *p) for p in pts))
            self.assertEqual(ref_writer.strokes_bytes([s], linear, True), rec)
            # the same curve without a grid in a file without the flag: no grid byte at all
            plain = s[:6]
            self.assertEqual(strokes_np.StrokeTable.from_tuples([plain]).record_bytes(linear),
                             head[:-5] + struct.pack("<I", 2) + rec[len(head):])

    def test_flag_without_grids_still_makes_format_1_4(self):
        inf, frames = spt_samples.animation(frames=2)
        inf.header.curve_grid = True
        p = self.path("flag.spt")
        write_stored(p, inf, frames)
        f = read_file(p)
        self.assertEqual((f.info.header.curve_grid, f.info.header.version_minor), (True, 4))
        self.assertEqual(list(f.live_lists()), list(ref_reader.read_file(p).live_lists()))

    def test_files_without_grids_keep_their_bytes(self):
        inf, frames = spt_samples.animation(frames=3)
        p = self.path("plain.spt")
        write_stored(p, inf, frames)
        h = read_file(p).info.header
        self.assertEqual((h.curve_grid, h.version_minor), (False, 0))
        self.assertEqual(struct.unpack_from("<I", read_all(p), 16 + 4)[0], 0, "HEAD flags")

    def test_writer_refuses_grids_it_cannot_store(self):
        inf, frames = spt_samples.animation(frames=1)
        frames[0].added.append((CURVE, 1, 2, 3, 255, ((16, 16, 16),), 4))
        with self.assertRaisesRegex(SptError, r"bad\.spt: frame 0: curve \d+: supersampling grid 4 needs the "
                                              r"HEAD flag curve_grid"):
            write_stored(self.path("bad.spt"), inf, frames)
        with self.assertRaisesRegex(SptError, "curve_grid"):
            ref_writer.strokes_bytes(frames[0].added)
        inf.header.curve_grid = True
        for grid in (1, 17, 255):
            frames[0].added[-1] = frames[0].added[-1][:6] + (grid,)
            with self.assertRaisesRegex(SptError, rf"frame 0: curve \d+: supersampling grid {grid} is not 0 or 2\.\.16"):
                write_stored(self.path("bad.spt"), inf, frames)
        self.assertFalse(os.path.exists(self.path("bad.spt")))

    def test_coded_round_trip_through_spt(self):
        """The Python writer's stored file, range-coded by `spt pack` (coding 1: curve_same_aa,
        curve_aa) and stored again: the same strokes and grids."""
        for linear in (False, True):
            inf, frames = aa_sample(linear)
            p, coded, back = self.path("aa.spt"), self.path("aa.coded.spt"), self.path("aa.back.spt")
            write_stored(p, inf, frames)
            spt("pack", p, "-o", coded)
            self.assertEqual(read_all(coded)[20] & 2, 2, "the coded file keeps the flag (HEAD flags, byte 20)")
            spt("pack", coded, "--stored", "-o", back)
            self.assertEqual(list(read_file(back).live_lists()), list(read_file(p).live_lists()), f"linear={linear}")


class Geometry(unittest.TestCase):
    def test_points_to_curve_keeps_the_grid(self):
        pts = [(1.0, 2.0, 3.0), (10.03, -4.5, 0.5)]
        for grid in (0, 2, 16):
            got = geometry.points_to_curve(pts, (1, 2, 3, 200), grid)
            self.assertEqual(got, ref_geometry.points_to_curve(pts, (1, 2, 3, 200), grid))
            self.assertEqual(curve_grid_of(got), grid)
            self.assertEqual(len(got), 6 if grid == 0 else 7, "grid 0 keeps the tuple of format 1.3")
        for grid in (1, 17):
            self.assertIsNone(geometry.points_to_curve(pts, (1, 2, 3, 200), grid))
            self.assertIsNone(ref_geometry.points_to_curve(pts, (1, 2, 3, 200), grid))


class BadFiles(Tmp):
    """Reserved grids and HEAD flags are refused, naming the file and the byte."""

    def sample(self, linear=False):
        inf, frames = aa_sample(linear, frames=1)
        p = self.path("aa.spt")
        write_stored(p, inf, frames)
        return bytearray(read_all(p))

    def readers(self):
        return (lambda b: read_bytes(b, "x.spt", columnar=True), lambda b: ref_reader.read_bytes(b, "x.spt"))

    def test_reserved_curve_grid(self):
        for linear in (False, True):
            base = self.sample(linear)
            t, rec = first_curve_record(bytes(base))
            at = rec + (8 if linear else 5)  # kind, r, g, b, a[, r_lo, g_lo, b_lo], grid
            for grid in (1, 17, 255):
                d = bytearray(base)
                d[at] = grid
                fix_chunk_crc(d, t)
                for read in self.readers():
                    with self.assertRaisesRegex(SptError, rf"x\.spt: byte {rec}: curve supersampling {grid} is reserved"):
                        list(read(bytes(d)).live_lists())

    def test_reserved_head_flags(self):
        for bit in (2, 3, 31):
            d = self.sample()
            d[20 + bit // 8] |= 1 << (bit % 8)
            fix_chunk_crc(d, 8)
            for read in self.readers():
                with self.assertRaisesRegex(SptError, r"x\.spt: byte 8: reserved HEAD fields"):
                    read(bytes(d))

    def test_flag_needs_format_1_4(self):
        d = self.sample()
        d[18] = 3
        fix_chunk_crc(d, 8)
        with self.assertRaisesRegex(SptError, r"x\.spt: byte 8: anti-aliased curves .* need format 1\.4, "
                                              r"the file says 1\.3"):
            read_bytes(bytes(d), "x.spt")

    def test_a_flagless_reader_view_misreads_nothing(self):
        """Clearing the flag of a file with grids leaves records that no longer parse: the reader
        says so (a 1.3 reader would have rejected the flag; it must never read the grid byte as
        part of the point count)."""
        d = self.sample()
        d[20] &= ~2
        fix_chunk_crc(d, 8)
        for read in self.readers():
            with self.assertRaises(SptError):
                list(read(bytes(d)).live_lists())


if __name__ == "__main__":
    unittest.main()
