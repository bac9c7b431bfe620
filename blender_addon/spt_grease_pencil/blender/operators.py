"""Operators: import, export, paint to strokes. Errors become Blender error reports."""

import os
import traceback

import bpy
from bpy.props import BoolProperty, EnumProperty, StringProperty
from bpy_extras.io_utils import ExportHelper, ImportHelper

from ..io.model import SptError
from .. import spt_tool
from ..io import paint_options
from .preferences import spt_path

LAYERING = [
    ('AUTO', "Automatic", "Per kind for flat-colour paintings (files with polygons), else per stroke set"),
    ('KINDS', "Layer per kind", "Fills (polygons), lines (curves) and paint (stamps, affine strokes)"),
    ('SETS', "Layer per stroke set", "One layer per stroke set, coarse to fine, plus shapes and curves"),
    ('SINGLE', "Single layer", "All strokes in one layer, in the file's exact drawing order"),
]


def _fail(op, e):
    """Reports an error without a traceback in the user's face (the console keeps it)."""
    if isinstance(e, (SptError, spt_tool.SptToolError)):
        op.report({'ERROR'}, str(e))
    else:
        traceback.print_exc()
        op.report({'ERROR'}, f"unexpected error: {type(e).__name__}: {e} (details in the console)")
    return {'CANCELLED'}


def _select_only(context, obj):
    for o in context.view_layer.objects:
        o.select_set(False)
    obj.select_set(True)
    context.view_layer.objects.active = obj


def do_import(op, context, path, layering):
    from . import importer
    try:
        obj, summary = importer.import_file(context, path, spt_path(context), layering)
    except Exception as e:  # noqa: BLE001 - every failure becomes a report
        return _fail(op, e)
    _select_only(context, obj)
    msg = f"Imported {summary['strokes']} strokes in {summary['frames']} frames from {os.path.basename(path)}"
    if not summary["complete"]:
        op.report({'WARNING'}, f"{path}: incomplete file ({summary['problem']}); imported the complete frames")
    op.report({'INFO'}, msg)
    return {'FINISHED'}


# No 'UNDO' in bl_options: an undo push of millions of strokes costs gigabytes (see README).
class IMPORT_SCENE_OT_spt(bpy.types.Operator, ImportHelper):
    """Import a stroke animation (.spt) as a Grease Pencil object"""
    bl_idname = "import_scene.spt"
    bl_label = "Import Stroke Animation"
    bl_options = {'REGISTER'}

    filename_ext = ".spt"
    filter_glob: StringProperty(default="*.spt", options={'HIDDEN'})
    layering: EnumProperty(name="Layers", items=LAYERING, default='AUTO')

    def execute(self, context):
        return do_import(self, context, self.filepath, self.layering)


class EXPORT_SCENE_OT_spt(bpy.types.Operator, ExportHelper):
    """Export the active Grease Pencil object as a stroke animation (.spt)"""
    bl_idname = "export_scene.spt"
    bl_label = "Export Stroke Animation"
    bl_options = {'REGISTER'}

    filename_ext = ".spt"
    filter_glob: StringProperty(default="*.spt", options={'HIDDEN'})
    stored: BoolProperty(name="Stored (no range coding)",
                         description="Write the uncompressed stored coding without running spt pack",
                         default=False)

    @classmethod
    def poll(cls, context):
        from . import gp
        obj = context.active_object
        return obj is not None and obj.type == gp.OBJECT_TYPE

    def execute(self, context):
        from . import exporter
        try:
            summary = exporter.export_file(context, context.active_object, self.filepath,
                                           spt_path(context), self.stored)
        except Exception as e:  # noqa: BLE001
            return _fail(self, e)
        for w in summary["warnings"][:5]:
            self.report({'WARNING'}, w)
        self.report({'INFO'}, f"Exported {summary['strokes']} strokes in {summary['frames']} frames to "
                              f"{os.path.basename(self.filepath)}")
        return {'FINISHED'}


def paint_source(scene, settings):
    """(input for spt paint, frame range text or '') from the panel settings."""
    if settings.source == 'FILE':
        if not settings.filepath:
            raise SptError("choose a file, file pattern or video to paint")
        return bpy.path.abspath(settings.filepath), ""
    base = bpy.path.abspath(scene.render.filepath)
    if os.path.isdir(base) or base.endswith(os.sep):
        base = os.path.join(base, "")
    ext = scene.render.file_extension if scene.render.use_file_extension else ""
    if "#" not in os.path.basename(base):
        base += "####"
    return base + ext, f"{scene.frame_start}-{scene.frame_end}"


def scene_fps_text(scene) -> str:
    """The scene's frame rate as spt's --fps value: 24, or a fraction such as 30000/1001."""
    from fractions import Fraction
    fps = Fraction(scene.render.fps / scene.render.fps_base).limit_denominator(1001)
    return str(fps.numerator) if fps.denominator == 1 else f"{fps.numerator}/{fps.denominator}"


class SPT_OT_paint(bpy.types.Operator):
    """Paint the rendered frames (or a chosen file or video) into strokes with spt, then import them"""
    bl_idname = "spt.paint_strokes"
    bl_label = "Paint to Strokes"
    bl_options = {'REGISTER'}

    blocking: BoolProperty(name="Blocking", description="Wait for spt in the foreground "
                           "(always so in background mode)", default=False, options={'SKIP_SAVE'})

    _job = None
    _timer = None

    def _start(self, context):
        scene = context.scene
        st = scene.spt_paint
        source, frames = paint_source(scene, st)
        out = bpy.path.abspath(st.output) if st.output else spt_tool.temp_path()
        if os.path.isdir(out):
            raise SptError(f"output {out} is a folder; give a .spt file name")
        from .panel import OPTION_ROWS  # the panel's options: spt's option table
        opts = {"frames": frames}
        for r in OPTION_ROWS:
            v = getattr(st, paint_options.prop_name(r))
            opts[paint_options.prop_name(r)] = bpy.path.abspath(v) if r["kind"] == "path" and v else v
        if st.source == 'RENDER' or "#" in source or "%" in source:
            opts["fps"] = scene_fps_text(scene)  # image sequences carry no rate; a video keeps its own
        spt_tool.version(spt_path(context))  # a clear message when missing or too old
        return spt_tool.PaintJob(spt_path(context), source, out, opts)

    def _finish(self, context, job):
        st = context.scene.spt_paint
        st.running = False
        st.progress = 100.0
        return do_import(self, context, job.output, st.layering)

    def execute(self, context):
        st = context.scene.spt_paint
        try:
            job = self._start(context)
        except Exception as e:  # noqa: BLE001
            return _fail(self, e)
        if self.blocking or bpy.app.background:
            try:
                job.wait()
            except Exception as e:  # noqa: BLE001
                return _fail(self, e)
            return self._finish(context, job)
        SPT_OT_paint._job = job
        st.running = True
        st.cancel_requested = False
        st.progress = 0.0
        wm = context.window_manager
        self._timer = wm.event_timer_add(0.2, window=context.window)
        wm.modal_handler_add(self)
        return {'RUNNING_MODAL'}

    def modal(self, context, event):
        st = context.scene.spt_paint
        job = SPT_OT_paint._job
        if event.type == 'ESC' or st.cancel_requested:
            self._stop(context)
            job.cancel()
            self.report({'WARNING'}, "Painting cancelled")
            return {'CANCELLED'}
        if event.type != 'TIMER':
            return {'PASS_THROUGH'}
        st.progress = job.percent
        for area in context.screen.areas if context.screen else []:
            if area.type == 'PROPERTIES':
                area.tag_redraw()
        if job.poll() is None:
            return {'PASS_THROUGH'}
        self._stop(context)
        try:
            job.wait()
        except Exception as e:  # noqa: BLE001
            return _fail(self, e)
        return self._finish(context, job)

    def _stop(self, context):
        st = context.scene.spt_paint
        st.running = False
        st.cancel_requested = False
        if self._timer is not None:
            context.window_manager.event_timer_remove(self._timer)
            self._timer = None
        SPT_OT_paint._job = None


class SPT_OT_paint_cancel(bpy.types.Operator):
    """Stop the running spt paint"""
    bl_idname = "spt.paint_cancel"
    bl_label = "Cancel"

    def execute(self, context):
        context.scene.spt_paint.cancel_requested = True
        return {'FINISHED'}


def menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_spt.bl_idname, text="Stroke animation (.spt)")


def menu_export(self, context):
    self.layout.operator(EXPORT_SCENE_OT_spt.bl_idname, text="Stroke animation (.spt)")


classes = (IMPORT_SCENE_OT_spt, EXPORT_SCENE_OT_spt, SPT_OT_paint, SPT_OT_paint_cancel)
