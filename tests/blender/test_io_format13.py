"""Format 1.3 in the add-on's bpy-free file layer (python3 -m unittest, no Blender needed): alpha
canvases and colour encoding 1 (scene-linear half-float codes) read, written byte for byte,
checked against the tuple oracle in reference/, and the half code <-> float conversions that make
a linear colour survive Grease Pencil exactly."""

import os
import random
import struct
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import spt_samples  # noqa: E402  (puts blender_addon on sys.path)
from chunk_util import Tmp, fix_chunk_crc, read_all  # noqa: E402

import numpy as np  # noqa: E402
from reference import ref_reader, ref_writer  # noqa: E402
from spt_grease_pencil.io import colors, stream_json, strokes_np  # noqa: E402
from spt_grease_pencil.io.model import (AFFINE, CURVE, KEY, LINEAR_HALF, POLYGON, STAMP, Frame, Limits,  # noqa: E402
                                        SptError)
from spt_grease_pencil.io.reader import read_bytes, read_file  # noqa: E402
from spt_grease_pencil.io.writer import write_stored  # noqa: E402

GOLDEN = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "format", "golden")
NEW = ("alpha_rgba", "linear_hdr", "linear_alpha")


def golden(name):
    return os.path.join(GOLDEN, name + ".stored.spt")


def fix_head_crc(d: bytearray) -> bytearray:
    fix_chunk_crc(d, 8)
    return d


def q24_to_half(v: int) -> int:
    """SPEC.md 8.6's code(L): the code nearest to v * 2^-24, ties to the even code."""
    if v < 2048:
        return v
    s = v.bit_length() - 11
    q, r = v >> s, v & ((1 << s) - 1)
    if r > 1 << (s - 1) or (r == 1 << (s - 1) and q & 1):
        q += 1
    if q == 2048:
        q, s = 1024, s + 1
    return min(((s + 1) << 10) | (q - 1024), 0x7BFF)


class GoldenFiles(Tmp):
    """The three format 1.3 golden files written by libspt (tests/format/golden)."""

    def test_headers(self):
        want = {"alpha_rgba": (True, 0), "linear_hdr": (False, LINEAR_HALF), "linear_alpha": (True, LINEAR_HALF)}
        for name, (alpha, enc) in want.items():
            h = read_file(golden(name)).info.header
            self.assertEqual((h.alpha, h.color_encoding, h.version_minor), (alpha, enc, 3), name)
        # linear_hdr's mid-grey background: code 0x31C3 = 0.18 (high bytes 0x31, low bytes 0xC3)
        h = read_file(golden("linear_hdr")).info.header
        self.assertEqual((h.background, h.background_lo), ((0x31,) * 3, (0xC3,) * 3))
        self.assertEqual(h.background_values(), (0x31C3,) * 3)
        self.assertAlmostEqual(float(colors.half_to_float(0x31C3)), 0.18, places=3)

    def test_rewrite_is_byte_identical(self):
        for name in NEW:
            for columnar in (False, True):
                f = read_file(golden(name), columnar=columnar)
                self.assertTrue(f.complete, name)
                out = self.path(name + ".spt")
                write_stored(out, f.info, f.frames)
                self.assertEqual(read_all(out), read_all(golden(name)), f"{name} columnar={columnar}")

    def test_numpy_reader_agrees_with_the_oracle(self):
        for name in NEW:
            ref = list(ref_reader.read_file(golden(name)).live_lists())
            got = [t.to_tuples() for t in read_file(golden(name), columnar=True).live_lists()]
            self.assertEqual(got, ref, name)
            linear = read_file(golden(name)).info.header.linear
            for ls in ref:  # and packs them back as the oracle does
                self.assertEqual(strokes_np.StrokeTable.from_tuples(ls).record_bytes(linear),
                                 ref_writer.strokes_bytes(ls, linear), name)

    def test_linear_colours_are_codes(self):
        """linear_hdr holds a stamp at 20.0, colours in the half subnormals and a stroke at 65504:
        the tuples carry the whole 16-bit codes."""
        live = list(read_file(golden("linear_hdr")).live_lists())[0]
        codes = {c for s in live for c in strokes_np.StrokeTable.from_tuples([s]).rows[0, strokes_np.R:strokes_np.B + 1]}
        values = colors.half_to_float(sorted(codes))
        self.assertIn(20.0, values.tolist())
        self.assertIn(0x7BFF, codes)
        self.assertTrue(any(0 < c < 0x400 for c in codes), "a subnormal code")
        self.assertTrue(any(c & 255 for c in codes), "low bytes that are not 0")

    def test_stream_json_keeps_the_new_header_fields(self):
        for name in NEW:
            info = read_file(golden(name)).info
            back = stream_json.from_json(stream_json.to_json(info))
            for field in ("alpha", "color_encoding", "background", "background_lo"):
                self.assertEqual(getattr(back.header, field), getattr(info.header, field), f"{name} {field}")


def linear_sample(alpha=True):
    """A small linear file of every kind, with codes above 1.0 and low bytes set."""
    inf = spt_samples.info()
    h = inf.header
    h.alpha, h.color_encoding = alpha, LINEAR_HALF
    h.set_background_values((0x3C00, 0x2E66, 0x0001))   # 1.0, 0.1, the smallest subnormal
    strokes = [(STAMP, 0, 0, 1, 8 + 16 * 20, 8 + 16 * 10, 0x4D00, 0x3C01, 0x0123, 255),
               (AFFINE, 1, 800, 600, 320, 48, -64, 160, 0x7BFF, 0x0000, 0x3555, 77),
               (CURVE, 0x4900, 0x2A3B, 0x3C00, 200, ((100, 100, 32), (900, 400, 64))),
               (POLYGON, 0x1234, 0x5678, 0x7BFE, 128, 4, ((160, 320), (480, 320), (300, 600)))]
    return inf, [Frame(0, KEY, added=strokes), Frame(1, KEY, added=strokes[1:])]


class Written(Tmp):
    def test_round_trip(self):
        for alpha in (False, True):
            inf, frames = linear_sample(alpha)
            p = self.path("lin.spt")
            write_stored(p, inf, frames)
            f = read_file(p)
            self.assertEqual((f.info.header.alpha, f.info.header.linear, f.info.header.version_minor), (alpha, True, 3))
            self.assertEqual(f.info.header.background_values(), (0x3C00, 0x2E66, 0x0001))
            self.assertEqual([list(x) for x in f.live_lists()], [frames[0].added, frames[1].added])
            self.assertEqual(list(ref_reader.read_file(p).live_lists()), [frames[0].added, frames[1].added])
            p2 = self.path("lin2.spt")
            write_stored(p2, read_file(p, columnar=True).info, read_file(p, columnar=True).frames)
            self.assertEqual(read_all(p2), read_all(p))

    def test_alpha_only_keeps_8_bit_records(self):
        inf, frames = spt_samples.animation(frames=3)
        p0, p1 = self.path("plain.spt"), self.path("alpha.spt")
        write_stored(p0, inf, frames)
        inf.header.alpha = True
        write_stored(p1, inf, frames)
        f0, f1 = read_file(p0), read_file(p1)
        self.assertEqual((f1.info.header.alpha, f1.info.header.version_minor), (True, 3))
        self.assertEqual(list(f1.live_lists()), list(f0.live_lists()))
        self.assertEqual(len(read_all(p1)), len(read_all(p0)))  # same records, one flag

    def test_writer_refuses_what_the_records_cannot_hold(self):
        inf, frames = linear_sample()
        frames[0].added[0] = frames[0].added[0][:6] + (0x7C00, 0, 0, 255)  # infinity
        with self.assertRaisesRegex(SptError, r"frame 0: .*0x7BFF"):
            write_stored(self.path("bad.spt"), inf, frames)
        self.assertFalse(os.path.exists(self.path("bad.spt")))
        inf, frames = spt_samples.animation(frames=1)
        frames[0].added = [s for s in frames[0].added if s[0] == STAMP][:1]
        frames[0].added[0] = frames[0].added[0][:6] + (0x3C00, 0, 0, 255)  # a code in an sRGB file
        with self.assertRaisesRegex(SptError, r"0\.\.255 \(colour encoding 0\)"):
            write_stored(self.path("bad.spt"), inf, frames)


class BadHeaders(unittest.TestCase):
    def head(self, name="linear_alpha"):
        return bytearray(read_all(golden(name)))

    def test_unknown_colour_encoding(self):
        d = self.head()
        d[16 + 28] = 2
        with self.assertRaisesRegex(SptError, r"x\.spt: byte 8: colour encoding 2 is not supported"):
            read_bytes(bytes(fix_head_crc(d)), "x.spt")

    def test_new_features_need_minor_3(self):
        for name in NEW:
            d = self.head(name)
            d[18] = 2
            with self.assertRaisesRegex(SptError, "needs format 1.3, the file says 1.2"):
                read_bytes(bytes(fix_head_crc(d)), "x.spt")

    def test_reserved_flags_and_byte(self):
        # Bit 1 is curve_grid since format 1.4 (test_io_format14.py); bits 2..31 stay reserved.
        for bit in (2, 7, 31):
            d = self.head()
            d[20 + bit // 8] |= 1 << (bit % 8)
            with self.assertRaisesRegex(SptError, "reserved HEAD fields"):
                read_bytes(bytes(fix_head_crc(d)), "x.spt")
        d = self.head()
        n = struct.unpack_from("<I", d, 8)[0]
        d[16 + n - 1] = 1  # the reserved byte after background_lo
        with self.assertRaisesRegex(SptError, "reserved HEAD byte"):
            read_bytes(bytes(fix_head_crc(d)), "x.spt")

    def test_background_code_above_half_range(self):
        d = self.head()
        d[16 + 29] = 0x7C  # background R high byte: 0x7C.. is infinity
        with self.assertRaisesRegex(SptError, "background colour code"):
            read_bytes(bytes(fix_head_crc(d)), "x.spt")

    def test_stroke_code_above_half_range(self):
        inf, frames = linear_sample()
        with tempfile.TemporaryDirectory() as tmp:
            p = os.path.join(tmp, "a.spt")
            write_stored(p, inf, frames)
            data = bytearray(read_all(p))
        t = data.find(b"FRAM")              # frame 0's type; its payload follows
        i = t + 4 + 8 + 4                   # its first record: the stamp
        data[i + 12] = 0x7C                 # the stamp's R high byte: code 0x7C00, infinity
        fix_chunk_crc(data, t - 4)
        for read in (lambda b: read_bytes(b, "x.spt", columnar=True), lambda b: ref_reader.read_bytes(b, "x.spt")):
            with self.assertRaisesRegex(SptError, r"x\.spt: byte \d+: colour code"):
                list(read(bytes(data)).live_lists())


class HalfCodes(unittest.TestCase):
    def test_every_code_survives_float32(self):
        codes = np.arange(0x7C00)
        values = colors.half_to_float(codes)
        self.assertEqual(values.dtype, np.float32)
        self.assertEqual(colors.float_to_half(values).tolist(), codes.tolist())
        self.assertEqual(float(values[0x7BFF]), 65504.0)
        self.assertEqual(float(values[1]), 2.0 ** -24)
        self.assertEqual(float(values[0x3C00]), 1.0)

    def test_nearest_code_ties_to_even_as_spec_8_6(self):
        rng = random.Random(3)
        vals = [0.0, 2.0 ** -25, 3 * 2.0 ** -25, 1.0 + 2.0 ** -11, 1.0 + 3 * 2.0 ** -11, 65504.0]
        vals += [rng.uniform(0, 1) ** 6 * 70000 for _ in range(3000)] + [rng.uniform(0, 2.0 ** -14) for _ in range(500)]
        got = colors.float_to_half(vals).tolist()
        for v, c in zip(vals, got):
            q = v * 2.0 ** 24
            self.assertEqual(c, q24_to_half(int(q)) if q == int(q) else self.brute(q), v)

    def brute(self, q):
        """The code whose value is nearest q * 2^-24 (even one on a tie), by search."""
        c = q24_to_half(int(q))
        best = None
        for k in (c - 1, c, c + 1):
            if 0 <= k <= 0x7BFF:
                d = abs(float(colors.half_to_float(k)) * 2.0 ** 24 - q)
                if best is None or d < best[0] or (d == best[0] and k % 2 == 0):
                    best = (d, k)
        return best[1]

    def test_out_of_range_values(self):
        self.assertEqual(colors.float_to_half([-1.0, -0.0, float("nan"), float("inf"), 1e9, 65519.0]).tolist(),
                         [0, 0, 0, 0x7BFF, 0x7BFF, 0x7BFF])

    def test_srgb_values_unchanged(self):
        codes = np.arange(256)
        lin = colors.values_to_linear(codes, False)
        self.assertEqual(colors.linear_to_values(lin, False).tolist(), codes.tolist())
        self.assertEqual(lin.tolist(), [colors.to_linear(k) for k in range(256)])


if __name__ == "__main__":
    unittest.main()
