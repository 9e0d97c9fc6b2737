"""Every pass (issue 21): cycles_contact's shot (a box sliding on a lit floor with its contact
shadow, a thin railing before a brick wall, a glossy sphere, 3 bounces) with a glass sphere for
the transmission passes and an emissive strip for the emission pass. Rendered with every pass a
comp uses on (render_passes_shot.py): the resolve must keep the passes consistent with the
beauty, and its Cryptomatte mattes must follow the resolved edges."""
import bpy

from . import build as b
from . import contact

DESCRIPTION = ('Cycles: cycles_contact with a glass sphere and an emissive strip, every light, '
               'colour and data pass and Cryptomatte on')

MOVING = contact.MOVING
MAX_BOUNCES = contact.MAX_BOUNCES


def glass(name, color):
    material = bpy.data.materials.new(name)
    nodes = b.Nodes(material)
    shader = nodes.new('ShaderNodeBsdfGlass')
    shader.inputs['Color'].default_value = color
    shader.inputs['Roughness'].default_value = 0.05
    nodes.link(shader.outputs['BSDF'], nodes.output.inputs['Surface'])
    return material


def emissive(name, color, strength):
    material = bpy.data.materials.new(name)
    nodes = b.Nodes(material)
    shader = nodes.new('ShaderNodeEmission')
    shader.inputs['Color'].default_value = color
    shader.inputs['Strength'].default_value = strength
    nodes.link(shader.outputs['Emission'], nodes.output.inputs['Surface'])
    return material


def build(frames):
    contact.build(frames)
    b.sphere('glass_ball', 0.4, glass('glass', (0.9, 0.95, 1.0, 1)), location=(0.9, 3.5, 0.4))
    b.box('strip', (2.0, 0.05, 0.06), emissive('strip', (1.0, 0.4, 0.1, 1), 3.0),
          location=(0.5, 5.4, 1.6))
