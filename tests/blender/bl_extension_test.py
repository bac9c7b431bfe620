"""Blender 4.2+ test: the extension zip as a user installs it. `blender --command extension
validate` accepts it, `blender --command extension install-file` installs it, and Preferences >
Get Extensions > Install from Disk (bpy.ops.extensions.package_install_files) installs and
enables it in this Blender; then its import and export work (unedited export identical)."""

import os
import subprocess
import sys

import bpy

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import bl_common as C  # noqa: E402

zip_path, spt, work, media = C.args()
C.check(bpy.app.version >= (4, 2, 0), "extensions need Blender 4.2+")
C.check(zip_path.endswith("-extension.zip"), f"{zip_path} is the extension zip")

r = subprocess.run([bpy.app.binary_path, "--command", "extension", "validate", zip_path],
                   capture_output=True, text=True)
C.check(r.returncode == 0, f"extension validate failed:\n{r.stdout}\n{r.stderr}")

cli_home = os.path.join(work, "cli-home")
r = subprocess.run([bpy.app.binary_path, "--command", "extension", "install-file", "-r", "user_default",
                    "-e", zip_path], capture_output=True, text=True, env=dict(os.environ, HOME=cli_home))
C.check(r.returncode == 0, f"extension install-file failed:\n{r.stdout}\n{r.stderr}")
ver = f"{bpy.app.version[0]}.{bpy.app.version[1]}"
installed = os.path.join(cli_home, ".config", "blender", ver, "extensions", "user_default", "spt_grease_pencil")
C.check(os.path.isfile(os.path.join(installed, "blender_manifest.toml")), f"install-file put it in {installed}")

# Install from Disk, the Preferences way, in this process.
r = bpy.ops.extensions.package_install_files(filepath=zip_path, repo="user_default", enable_on_install=True)
C.check(r == {'FINISHED'}, f"package_install_files returned {r}")
module = "bl_ext.user_default.spt_grease_pencil"
C.check(module in bpy.context.preferences.addons, f"{module} is enabled")
C.check(hasattr(bpy.ops.import_scene, "spt") and hasattr(bpy.ops.export_scene, "spt"), "operators registered")
bpy.context.preferences.addons[module].preferences.spt_path = spt

import importlib  # noqa: E402
io = importlib.import_module(module + ".io")
sys.modules["spt_grease_pencil"] = importlib.import_module(module)  # spt_samples imports it by name
sys.modules["spt_grease_pencil.io"] = io
import spt_samples  # noqa: E402

src = spt_samples.write_animation(os.path.join(work, "anim.stored.spt"), frames=3)
orig = list(io.read_file(src).live_lists())
before = set(bpy.data.objects)
C.check(bpy.ops.import_scene.spt(filepath=src) == {'FINISHED'}, "import")
obj = [o for o in bpy.data.objects if o not in before and o.type == 'GREASEPENCIL'][0]
bpy.context.view_layer.objects.active = obj
out = os.path.join(work, "unedited.spt")
C.check(bpy.ops.export_scene.spt(filepath=out, stored=True) == {'FINISHED'}, "export")
C.check(list(io.read_file(out).live_lists()) == orig, "unedited export through the extension is exact")
print("OK")
