"""Output properties > Paint to strokes: the painting settings and the progress bar.

The painting options are spt's own option table (io/paint_options.py): the rows marked for the
add-on become properties here, and a new row in spt's table appears in the panel with no edit."""

import bpy
from bpy.props import BoolProperty, EnumProperty, FloatProperty, IntProperty, StringProperty

from ..io import paint_options
from .operators import LAYERING


def _option_property(row):
    """The Blender property of one option row (0 or empty: spt's default)."""
    name, desc, kind = paint_options.label(row), row["help"], row["kind"]
    if kind == "choice":
        items = [(paint_options.enum_id(c), c.capitalize(), desc) for c in row["choices"]]
        return EnumProperty(name=name, items=items, description=desc,
                            default=paint_options.enum_id(row.get("default", row["choices"][0])))
    if kind == "integer":
        return IntProperty(name=name, default=0, min=0, max=int(row["max"]), description=desc + " (0: spt's default)")
    if kind == "number":
        return FloatProperty(name=name, default=0.0, min=0.0, max=float(row["max"]), description=desc + " (0: none)")
    if kind == "flag":
        return BoolProperty(name=name, default=False, description=desc)
    if paint_options.is_number_text(row):
        return IntProperty(name=name, default=int(row["default"]), min=0, description=desc)
    if kind == "path":
        return StringProperty(name=name, subtype='DIR_PATH' if row.get("metavar") == "DIR" else 'FILE_PATH',
                              description=desc)
    return StringProperty(name=name, default=row.get("default", ""), description=desc)


OPTION_ROWS = paint_options.panel_rows(paint_options.load())

_annotations = {
    "source": EnumProperty(name="Source", items=[
        ('RENDER', "Rendered frames", "The frames the scene renders to its output path"),
        ('FILE', "File", "An image, an image sequence pattern (frame_####.png) or a video"),
    ], default='RENDER'),
    "filepath": StringProperty(name="File", subtype='FILE_PATH',
                               description="Image, sequence pattern (####) or video to paint"),
    "output": StringProperty(name="Output .spt", subtype='FILE_PATH', default="//painted.spt",
                             description="Where spt writes the painting (empty: a temporary file)"),
}
_annotations.update({paint_options.prop_name(r): _option_property(r) for r in OPTION_ROWS})
_annotations.update({
    "layering": EnumProperty(name="Layers", items=LAYERING, default='AUTO'),
    "progress": FloatProperty(name="Progress", subtype='PERCENTAGE', min=0.0, max=100.0, default=0.0),
    "running": BoolProperty(default=False),
    "cancel_requested": BoolProperty(default=False),
})
SPT_PaintSettings = type("SPT_PaintSettings", (bpy.types.PropertyGroup,), {"__annotations__": _annotations})


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
        style = st.style.lower()
        for r in OPTION_ROWS:
            row = col.row()
            row.active = paint_options.applies(r, style)  # e.g. the cartoon painter takes no ROIs
            row.prop(st, paint_options.prop_name(r))
        col.prop(st, "layering")
        if st.running:
            row = layout.row()
            row.enabled = False  # a read-only slider is the 3.4 progress bar
            row.prop(st, "progress", slider=True)
            layout.operator("spt.paint_cancel", icon='CANCEL')
        else:
            layout.operator("spt.paint_strokes", icon='BRUSH_DATA')


classes = (SPT_PaintSettings, SPT_PT_paint)
