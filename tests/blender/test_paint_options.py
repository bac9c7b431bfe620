"""The add-on's option layer (io/paint_options.py) against spt's own table: the table shipped with
the add-on is what `spt paint --options-json` prints, and the arguments the panel builds are ones
spt accepts, leaving out defaults and the options a style does not take."""

import json
import os
import subprocess
import sys
import tempfile
import unittest

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "blender_addon"))
from spt_grease_pencil.io import paint_options  # noqa: E402  (no bpy needed)

SPT = sys.argv.pop(1) if len(sys.argv) > 1 else os.environ.get("SPT_TOOL", "")


class ShippedTable(unittest.TestCase):
    def test_the_shipped_table_is_the_commands(self):
        self.assertTrue(SPT and os.path.isfile(SPT), f"spt is needed: '{SPT}'")
        out = subprocess.run([SPT, "paint", "--options-json"], capture_output=True, text=True, check=True).stdout
        with open(paint_options.TABLE, encoding="utf-8") as f:
            shipped = f.read()
        self.assertEqual(shipped, out, "blender_addon/spt_grease_pencil/paint_options.json is stale: "
                                       "write it again with `spt paint --options-json`")

    def test_panel_rows_come_from_the_table(self):
        rows = paint_options.load()
        names = [r["name"] for r in paint_options.panel_rows(rows)]
        self.assertEqual(names[0], "style")
        for n in ("seed", "sets", "max-strokes", "target-psnr", "templates", "roi-file", "keyframe-interval"):
            self.assertIn(n, names)
        self.assertNotIn("threads", names)


class Arguments(unittest.TestCase):
    def setUp(self):
        self.rows = paint_options.load()

    def test_defaults_and_zero_are_left_out(self):
        self.assertEqual(paint_options.paint_args(self.rows, {"style": "PAINTERLY", "sets": 0, "target_psnr": 0.0,
                                                              "templates": "", "seed": 1}), ["--seed", "1"])

    def test_a_style_takes_only_its_options(self):
        v = {"style": "CARTOON", "roi_file": "/r.json", "target_psnr": 31.5, "seed": 2}
        self.assertEqual(paint_options.paint_args(self.rows, v),
                         ["--style", "cartoon", "--seed", "2", "--target-psnr", "31.5"])
        self.assertIn("--roi-file", paint_options.paint_args(self.rows, dict(v, style="PAINTERLY")))

    def test_spt_accepts_what_the_panel_builds(self):
        self.assertTrue(SPT and os.path.isfile(SPT), f"spt is needed: '{SPT}'")
        v = {"style": "PAINTERLY", "sets": 4, "max_strokes": 50, "target_psnr": 20.0, "keyframe_interval": 3, "seed": 7}
        args = paint_options.paint_args(self.rows, v)
        with tempfile.TemporaryDirectory() as d:
            src, out = os.path.join(d, "in.ppm"), os.path.join(d, "out.spt")
            with open(src, "wb") as f:
                f.write(b"P6 16 16 255\n" + bytes((x * 16) % 256 for x in range(16 * 16 * 3)))
            r = subprocess.run([SPT, "paint", src, "-o", out, "--progress", "none"] + args, capture_output=True, text=True)
            self.assertEqual(r.returncode, 0, r.stderr)
            self.assertTrue(os.path.isfile(out))


if __name__ == "__main__":
    unittest.main()
