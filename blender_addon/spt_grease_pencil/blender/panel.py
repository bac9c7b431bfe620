"""Output properties > Paint to strokes: the painting settings and the progress bar."""

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

from .operators import LAYERING


class SPT_PaintSettings(bpy.types.PropertyGroup):
    source: EnumProperty(name="Source", items=[
        ('RENDER', "Rendered frames", "The frames the scene renders to its output path"),
        ('FILE', "File", "An image, an image sequence pattern (frame_####.png) or a video"),
    ], default='RENDER')
    filepath: StringProperty(name="File", subtype='FILE_PATH',
                             description="Image, sequence pattern (####) or video to paint")
    style: EnumProperty(name="Style", items=[
        ('PAINTERLY', "Painterly", "Brush strokes over the picture (spt's default painter)"),
        ('CARTOON', "Cartoon", "Flat-colour art (toon renders, cartoons): filled shapes and drawn lines, "
                               "brush strokes only where they leave an error (spt paint --style cartoon)"),
    ], default='PAINTERLY')
    output: StringProperty(name="Output .spt", subtype='FILE_PATH', default="//painted.spt",
                           description="Where spt writes the painting (empty: a temporary file)")
    sets: IntProperty(name="Stroke sets", default=0, min=0, max=10,
                      description="Number of stroke sets, coarse to fine: 3..10 (0: spt's default)")
    max_strokes: IntProperty(name="Max strokes", default=0, min=0,
                             description="Stop a frame at this many strokes (0: spt's default)")
    target_psnr: FloatProperty(name="Target PSNR", default=0.0, min=0.0, max=99.0,
                               description="Stop a frame when it reaches this PSNR in dB (0: none)")
    templates: StringProperty(name="Templates", subtype='DIR_PATH',
                              description="Folder of grayscale brush templates (empty: built-in)")
    key_interval: IntProperty(name="Key frame interval", default=0, min=0,
                              description="Frames between key frames (0: spt's default)")
    roi: StringProperty(name="ROI file", subtype='FILE_PATH',
                        description="Regions of interest painted down to the finest set: JSON "
                              "{\"rois\":[{\"x\":..,\"y\":..,\"w\":..,\"h\":..}]}")
    seed: IntProperty(name="Seed", default=1, min=0, description="Same seed, same strokes")
    layering: EnumProperty(name="Layers", items=LAYERING, default='AUTO')
    progress: FloatProperty(name="Progress", subtype='PERCENTAGE', min=0.0, max=100.0, default=0.0)
    running: BoolProperty(default=False)
    cancel_requested: BoolProperty(default=False)


class SPT_PT_paint(bpy.types.Panel):
    bl_label = "Paint to Strokes"
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = "output"
    bl_options = {'DEFAULT_CLOSED'}

    def draw(self, context):
        st = context.scene.spt_paint
        layout = self.layout
        layout.use_property_split = True
        col = layout.column()
        col.enabled = not st.running
        col.prop(st, "source")
        if st.source == 'FILE':
            col.prop(st, "filepath")
        col.prop(st, "output")
        col.prop(st, "style")
        col.prop(st, "sets")
        col.prop(st, "max_strokes")
        col.prop(st, "target_psnr")
        col.prop(st, "templates")
        col.prop(st, "key_interval")
        roi = col.row()
        roi.active = st.style != 'CARTOON'  # the cartoon painter paints the whole frame
        roi.prop(st, "roi")
        col.prop(st, "seed")
        col.prop(st, "layering")
        if st.running:
            row = layout.row()
            row.enabled = False  # a read-only slider is the 3.4 progress bar
            row.prop(st, "progress", slider=True)
            layout.operator("spt.paint_cancel", icon='CANCEL')
        else:
            layout.operator("spt.paint_strokes", icon='BRUSH_DATA')


classes = (SPT_PaintSettings, SPT_PT_paint)
