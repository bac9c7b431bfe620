"""Shared set-up of the Blender tests: command-line arguments and installing the add-on from the
built zip the way a user does. Run as: blender -b --factory-startup --python-exit-code 1
--python <test>.py -- ZIP SPT_TOOL WORKDIR [MEDIA_DIR]"""

import os
import sys

import bpy

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

SKIP = 1  # a missing part fails the test: a test never passes by skipping


def args():
    a = sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []
    while len(a) < 4:
        a.append("")
    zip_path, spt, work, media = a[:4]
    os.makedirs(work, exist_ok=True)
    return zip_path, spt, work, media


def install(zip_path, spt=""):
    import addon_utils
    bpy.ops.preferences.addon_install(filepath=zip_path, overwrite=True)
    mod = addon_utils.enable("spt_grease_pencil", default_set=True, handle_error=None)
    assert mod is not None, "the add-on did not enable"
    prefs = bpy.context.preferences.addons["spt_grease_pencil"].preferences
    prefs.spt_path = spt
    return prefs


def spt_works(spt, command):
    """True when `spt COMMAND --help` exits 0 (the command is implemented)."""
    import subprocess
    if not spt or not os.path.isfile(spt):
        return False
    r = subprocess.run([spt, command, "--help"], capture_output=True, text=True)
    return r.returncode == 0 and "not implemented" not in (r.stdout + r.stderr)


def stored_lists(spt, coded, back):
    """`spt pack CODED --stored -o BACK`; returns BACK's live stroke lists (the add-on's reader)."""
    import subprocess
    from spt_grease_pencil.io import read_file
    subprocess.run([spt, "pack", coded, "--stored", "-o", back], check=True)
    return list(read_file(back).live_lists())


def renders_identically(spt, a, b, frames):
    """spt renders files a and b (paths) to the same PNG bytes, frame by frame (beside them)."""
    import subprocess
    for name in (a, b):
        r = subprocess.run([spt, "render", name, "-o", name + ".####.png"], capture_output=True, text=True)
        check(r.returncode == 0, f"spt render {name}: {r.stderr}")
    for fi in range(frames):
        with open(f"{a}.{fi:04d}.png", "rb") as fa, open(f"{b}.{fi:04d}.png", "rb") as fb:
            check(fa.read() == fb.read(), f"frame {fi} of {b} renders as {a}")


def reset_scene():
    bpy.ops.wm.read_factory_settings(use_empty=True)


def fail(msg):
    print("FAIL:", msg)
    sys.exit(1)


def check(cond, msg):
    if not cond:
        fail(msg)


def import_spt(path, layering='SETS'):
    """Imports `path` with the add-on's operator; returns the one new Grease Pencil object."""
    before = set(bpy.data.objects)
    r = bpy.ops.import_scene.spt(filepath=path, layering=layering)
    check(r == {'FINISHED'}, f"import returned {r}")
    import bl_gp
    new = [o for o in bpy.data.objects if o not in before and o.type == bl_gp.OBJECT_TYPE]
    check(len(new) == 1, "import made one Grease Pencil object")
    return new[0]


def export_spt(obj, path, stored=True):
    """Exports `obj` to `path`; returns the file's live stroke lists when stored (read back with
    the add-on's own reader), else None."""
    from spt_grease_pencil.io import read_file
    bpy.context.view_layer.objects.active = obj
    r = bpy.ops.export_scene.spt(filepath=path, stored=stored)
    check(r == {'FINISHED'}, f"export returned {r}")
    return list(read_file(path).live_lists()) if stored else None
