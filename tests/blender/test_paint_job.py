"""The add-on's subprocess layer without Blender: PaintJob runs a real `spt paint`, and Cancel
stops it cleanly (the process ends, the reader threads end, no output or temporary file is left,
an existing output is not touched). usage: python3 test_paint_job.py SPT [MEDIA_DIR]
Fails when spt is not built."""

import os
import sys
import tempfile
import time
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "blender_addon"))
from spt_grease_pencil import spt_tool  # noqa: E402  (no bpy needed)

SPT = sys.argv[1] if len(sys.argv) > 1 else ""
MEDIA = sys.argv[2] if len(sys.argv) > 2 else ""


def image_rows(w, h):
    """A busy test image (no numpy, no PIL): rings and stripes; rows of RGB bytes."""
    rows = []
    for y in range(h):
        px = bytearray()
        for x in range(w):
            r = ((x - w // 2) ** 2 + (y - h // 2) ** 2) // 97 % 2
            px += bytes((255 * r, (x * 7 + y * 3) % 256, (x ^ y) % 256))
        rows.append(bytes(px))
    return rows


def write_ppm(path, w=256, h=192, shift=0, rows=None):
    rows = rows or image_rows(w, h)
    s = 3 * (shift % w)
    with open(path, "wb") as f:
        f.write(b"P6 %d %d 255\n" % (w, h) + b"".join(r[s:] + r[:s] for r in rows))


def write_sequence(folder, frames, w=160, h=120, distinct=20):
    """f.0001.ppm ... : the test image panning one pixel a frame, `distinct` images repeated
    (links) up to `frames` frames: a long paint made of cheap files."""
    os.mkdir(folder)
    rows = image_rows(w, h)
    for k in range(1, frames + 1):
        p = os.path.join(folder, f"f.{k:04d}.ppm")
        if k <= distinct:
            write_ppm(p, w, h, k, rows)
        else:
            os.link(os.path.join(folder, f"f.{(k - 1) % distinct + 1:04d}.ppm"), p)
    return os.path.join(folder, "f.####.ppm")


class Cancel(unittest.TestCase):
    def setUp(self):
        self.tmp = tempfile.TemporaryDirectory()
        self.dir = self.tmp.name
        self.src = os.path.join(self.dir, "in.ppm")
        write_ppm(self.src)

    def tearDown(self):
        self.tmp.cleanup()

    def long_job(self, out):
        # 2000 frames, each a key frame painted fully: about a minute of painting (cancelled
        # after a second). On SIGTERM a sequence paint finishes its frame and writes what it has
        # (spt paint --help): the job must still leave nothing behind.
        src = write_sequence(os.path.join(self.dir, "seq"), 2000)
        return spt_tool.PaintJob(SPT, src, out, {"max_strokes": 400000, "sets": 6, "seed": 1, "frames": "1-2000",
                                                 "keyframe_interval": 1})

    def started(self, job):
        deadline = time.time() + 20
        while job.percent <= 0 and job.poll() is None and time.time() < deadline:
            time.sleep(0.05)  # until the first progress line: spt is really painting
        self.assertIsNone(job.poll(), "spt paint ended before it could be cancelled")
        self.assertGreater(job.percent, 0.0, "progress lines arrive through the reader thread")

    def test_cancel_stops_and_leaves_nothing(self):
        out = os.path.join(self.dir, "out.spt")
        job = self.long_job(out)
        before = sorted(os.listdir(self.dir))
        self.started(job)
        time.sleep(0.5)  # into the painting of a frame
        t = time.time()
        job.cancel()
        took = time.time() - t
        self.assertIsNotNone(job.poll(), "the process has ended")
        self.assertLess(took, job.grace + 5, "cancel returns promptly")
        self.assertTrue(job.cancelled)
        self.assertFalse(job._out.is_alive() or job._err.is_alive(), "reader threads ended")
        self.assertFalse(os.path.exists(out), "no output after Cancel")
        self.assertEqual(sorted(os.listdir(self.dir)), before, "no temporary or partial file left")

    def test_cancel_keeps_an_existing_output(self):
        out = os.path.join(self.dir, "keep.spt")
        with open(out, "wb") as f:
            f.write(b"an earlier painting")
        job = self.long_job(out)
        self.started(job)
        job.cancel()
        with open(out, "rb") as f:
            self.assertEqual(f.read(), b"an earlier painting")

    def test_finished_job_moves_its_result_into_place(self):
        out = os.path.join(self.dir, "small.spt")
        job = spt_tool.PaintJob(SPT, self.src, out, {"max_strokes": 50, "sets": 3, "seed": 2})
        job.wait()
        self.assertEqual(job.percent, 100.0)
        with open(out, "rb") as f:
            self.assertEqual(f.read(8), b"\x89SPT\r\n\x1a\n")
        self.assertEqual(sorted(os.listdir(self.dir)), ["in.ppm", "small.spt"])
        self.assertFalse(job.cancelled)

    def test_failure_is_a_readable_error(self):
        out = os.path.join(self.dir, "bad.spt")
        job = spt_tool.PaintJob(SPT, os.path.join(self.dir, "missing.png"), out, {"seed": 1})
        with self.assertRaises(spt_tool.SptToolError) as cm:
            job.wait()
        self.assertIn("spt paint failed", str(cm.exception))
        self.assertFalse(os.path.exists(out))


class CartoonJob(unittest.TestCase):
    """The panel's Cartoon style: a real paint of a short sequence reports progress and writes a
    cartoon; an ROI file set in the panel is not passed (the cartoon painter refuses ROIs)."""

    def test_cartoon_sequence_paints_with_progress_and_without_rois(self):
        with tempfile.TemporaryDirectory() as d:
            src = write_sequence(os.path.join(d, "seq"), 4)
            roi = os.path.join(d, "roi.json")
            with open(roi, "w") as f:
                f.write('{"rois":[{"x":1,"y":1,"w":8,"h":8}]}')
            opts = {"style": "cartoon", "target_psnr": 30, "seed": 1, "frames": "1-4", "roi_file": roi}
            self.assertNotIn("--roi-file", spt_tool.paint_args(opts))
            self.assertIn("--roi-file", spt_tool.paint_args(dict(opts, style="painterly")))
            out = os.path.join(d, "out.spt")
            job = spt_tool.PaintJob(SPT, src, out, opts)
            job.wait()
            self.assertTrue(os.path.isfile(out))
            with open(out, "rb") as f:
                data = f.read()
            self.assertIn(b"style=cartoon", data)
            self.assertEqual(job.percent, 100.0)


if __name__ == "__main__":
    if not SPT or not os.path.isfile(SPT):
        print(f"FAIL: spt not built ({SPT or 'no path given'})")
        sys.exit(1)
    suite = unittest.TestSuite([unittest.defaultTestLoader.loadTestsFromTestCase(c) for c in (Cancel, CartoonJob)])
    r = unittest.TextTestRunner(verbosity=2).run(suite)
    sys.exit(0 if r.wasSuccessful() else 1)
