"""Blender test: bad files and a missing spt end with an error report, not a traceback."""

import os
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bl_common as C  # noqa: E402

zip_path, spt, work, media = C.args()
C.install(zip_path, os.path.join(work, "no-such-spt"))
import spt_samples  # noqa: E402


def data_counts():
    gps = getattr(bpy.data, "grease_pencils_v3", bpy.data.grease_pencils)
    return {c: len(getattr(bpy.data, c)) for c in ("objects", "materials", "images", "cameras")} | \
        {"grease pencils": len(gps)}


def expect_error(path, words):
    before = data_counts()
    try:
        r = bpy.ops.import_scene.spt(filepath=path)
    except RuntimeError as e:  # background mode turns an ERROR report into RuntimeError
        msg = str(e)
        C.check("Traceback" not in msg, f"traceback in the report: {msg}")
        for w in words:
            C.check(w in msg, f"report '{msg}' should mention '{w}'")
        print("reported:", msg.strip())
        C.check(data_counts() == before, f"nothing half-made is left: {before} -> {data_counts()}")
        return
    C.fail(f"import of {path} returned {r} without an error report")


good = spt_samples.write_animation(os.path.join(work, "good.spt"), frames=2)
data = open(good, "rb").read()
bad = os.path.join(work, "bad_signature.spt")
open(bad, "wb").write(b"PK\x03\x04" + data[4:])
expect_error(bad, ["bad_signature.spt", "signature"])
bad = os.path.join(work, "bad_head.spt")
d = bytearray(data)
d[8 + 8] = 7  # version_major 7, CRC now wrong too
open(bad, "wb").write(bytes(d))
expect_error(bad, ["bad_head.spt"])
expect_error(os.path.join(work, "missing.spt"), ["missing.spt"])
# A range-coded frame needs spt pack, which is configured to a missing executable.
import struct, zlib  # noqa: E401,E402
d = bytearray(data)
i = d.find(b"FRAM") - 4
ln = struct.unpack_from("<I", d, i)[0]
d[i + 8 + 5] = 1
struct.pack_into("<I", d, i + 8 + ln, zlib.crc32(bytes(d[i + 4:i + 8 + ln])) & 0xFFFFFFFF)
coded = os.path.join(work, "coded.spt")
open(coded, "wb").write(bytes(d))
expect_error(coded, ["spt", "not found"])
# Blender failing half-way through an import (simulated in the backend's third frame): a
# readable report, and every object, material and image the import made is removed again.
from spt_grease_pencil.blender import gp  # noqa: E402
prefs = bpy.context.preferences.addons["spt_grease_pencil"].preferences
prefs.spt_path = spt
real_fill = gp.fill_frame
calls = []


def failing_fill(frame, batch):
    calls.append(1)
    if len(calls) > 2:
        raise MemoryError("simulated: Blender ran out of memory")
    return real_fill(frame, batch)


gp.fill_frame = failing_fill
expect_error(good, ["MemoryError", "simulated"])
gp.fill_frame = real_fill
C.check(len(calls) > 2, "the failure happened while frames were being built")
C.check(bpy.ops.import_scene.spt(filepath=good) == {'FINISHED'}, "the same file imports afterwards")
# Export without an active Grease Pencil object is refused by poll.
bpy.ops.object.select_all(action='DESELECT')
bpy.context.view_layer.objects.active = None
C.check(not bpy.ops.export_scene.spt.poll(), "export needs a Grease Pencil object")
print("OK")
