"""The scene's taa settings, the panel in Output Properties, and the render operator (the
headless entry point: blender -b shot.blend --python-expr "import bpy; bpy.ops.taa.render()")."""
import bpy

from . import requirements


class TaaRenderSettings(bpy.types.PropertyGroup):
    enabled: bpy.props.BoolProperty(
        name='taa',
        description='Jitter each frame by Halton(2,3) and write its camera into the EXR header '
                    '(the Note), with the settings taatool --preset cycles needs, during renders '
                    'of this scene; everything is put back after the render')
    write_sidecar: bpy.props.BoolProperty(
        name='Camera sidecar',
        description='Also write taatool\'s JSON camera sidecar (for pipelines that strip EXR '
                    'metadata)')
    sidecar_path: bpy.props.StringProperty(
        name='Sidecar', subtype='FILE_PATH',
        description='Where the sidecar goes (empty: taa_camera.json beside the frames)')


class TAA_OT_render(bpy.types.Operator):
    """Render this scene for taa: jittered frames with their cameras in the EXR headers"""
    bl_idname = 'taa.render'
    bl_label = 'Render for taa'

    animation: bpy.props.BoolProperty(name='Animation', default=True,
                                      description='The frame range (else the current frame)')

    def execute(self, context):
        scene = context.scene
        problems = requirements.blockers(scene)
        if problems:
            self.report({'ERROR'}, 'taa cannot render this scene: ' + '; '.join(problems))
            return {'CANCELLED'}
        scene.taa_render.enabled = True
        if bpy.app.background:
            bpy.ops.render.render(animation=self.animation, write_still=not self.animation)
        else:
            bpy.ops.render.render('INVOKE_DEFAULT', animation=self.animation,
                                  write_still=not self.animation)
        return {'FINISHED'}


class TAA_PT_render(bpy.types.Panel):
    bl_label = 'taa Temporal Anti-Aliasing'
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = 'output'
    bl_options = {'DEFAULT_CLOSED'}

    def draw_header(self, context):
        self.layout.prop(context.scene.taa_render, 'enabled', text='')

    def draw(self, context):
        scene = context.scene
        settings = scene.taa_render
        layout = self.layout
        for problem in requirements.blockers(scene):
            row = layout.row()
            row.alert = True
            row.label(text=problem, icon='ERROR')
        column = layout.column(align=True)
        column.label(text='During taa renders (put back afterwards):')
        for setting in requirements.settings(scene):
            wanted = setting.wanted_value(scene)
            if wanted is None:
                continue
            current = setting.get(scene)
            text = '%s: %s' % (setting.label, requirements.describe(wanted))
            if current != wanted:
                text += ' (now %s)' % requirements.describe(current)
            column.label(text=text, icon='CHECKMARK' if current == wanted else 'MODIFIER')
        column.label(text='Lens shift: + the frame\'s Halton jitter; camera note in "Note"',
                     icon='CAMERA_DATA')
        layout.prop(settings, 'write_sidecar')
        row = layout.row()
        row.enabled = settings.write_sidecar
        row.prop(settings, 'sidecar_path')
        layout.operator(TAA_OT_render.bl_idname, icon='RENDER_ANIMATION').animation = True


CLASSES = (TaaRenderSettings, TAA_OT_render, TAA_PT_render)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.taa_render = bpy.props.PointerProperty(type=TaaRenderSettings)


def unregister():
    del bpy.types.Scene.taa_render
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
