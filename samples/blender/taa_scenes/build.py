"""Building blocks of the yardstick's Blender scenes: meshes from vertex lists, emission and
lit materials with procedural textures, per-frame keyframed animation, the world.

Everything is made procedurally (no assets), and every material is noise-free at one sample
per pixel: emission, or direct light from radius-0 point lights with no bounces, so the only
error in a 1-spp render is aliasing.
"""
import math

import bpy
from mathutils import Matrix, Vector


# --- meshes -----------------------------------------------------------------------------------

def mesh_object(name, vertices, faces, material, smooth=False):
    """One object from a vertex and face list, linked to the scene."""
    mesh = bpy.data.meshes.new(name)
    mesh.from_pydata([tuple(v) for v in vertices], [], faces)
    mesh.update()
    if smooth:
        for polygon in mesh.polygons:
            polygon.use_smooth = True
    mesh.materials.append(material)
    obj = bpy.data.objects.new(name, mesh)
    bpy.context.scene.collection.objects.link(obj)
    return obj


def tubes(name, segments, radius, material, sides=6):
    """Thin prisms along (start, end) segments, all in one object: wires, fence mesh, rails."""
    vertices, faces = [], []
    for start, end in segments:
        start, end = Vector(start), Vector(end)
        axis = (end - start).normalized()
        helper = Vector((0, 0, 1)) if abs(axis.z) < 0.9 else Vector((1, 0, 0))
        u = axis.cross(helper).normalized()
        v = axis.cross(u)
        base = len(vertices)
        for point in (start, end):
            for k in range(sides):
                angle = 2.0 * math.pi * k / sides
                vertices.append(point + radius * (math.cos(angle) * u + math.sin(angle) * v))
        for k in range(sides):
            k1 = (k + 1) % sides
            faces.append((base + k, base + k1, base + sides + k1, base + sides + k))
        faces.append(tuple(base + k for k in reversed(range(sides))))
        faces.append(tuple(base + sides + k for k in range(sides)))
    return mesh_object(name, vertices, faces, material)


def box(name, size, material, location=(0, 0, 0), rotation=(0, 0, 0)):
    """An axis-aligned box of the given size (x, y, z), centred on its origin."""
    sx, sy, sz = (0.5 * s for s in size)
    vertices = [(x, y, z) for x in (-sx, sx) for y in (-sy, sy) for z in (-sz, sz)]
    faces = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    obj = mesh_object(name, vertices, faces, material)
    obj.location = location
    obj.rotation_euler = rotation
    return obj


def rectangle(name, width, height, material, location=(0, 0, 0), rotation=(0, 0, 0)):
    """A flat rectangle in its local x-y plane (normal +z), centred on its origin."""
    w, h = 0.5 * width, 0.5 * height
    obj = mesh_object(name, [(-w, -h, 0), (w, -h, 0), (w, h, 0), (-w, h, 0)], [(0, 1, 2, 3)],
                      material)
    obj.location = location
    obj.rotation_euler = rotation
    return obj


def sphere(name, radius, material, location=(0, 0, 0), segments=96, rings=48):
    """A smooth UV sphere (fine enough that its silhouette is round at 1080p)."""
    vertices = [(0, 0, radius)]
    for ring in range(1, rings):
        theta = math.pi * ring / rings
        for seg in range(segments):
            phi = 2.0 * math.pi * seg / segments
            vertices.append((radius * math.sin(theta) * math.cos(phi),
                             radius * math.sin(theta) * math.sin(phi), radius * math.cos(theta)))
    vertices.append((0, 0, -radius))
    bottom = len(vertices) - 1
    faces = [(0, 1 + s, 1 + (s + 1) % segments) for s in range(segments)]
    for ring in range(rings - 2):
        a, b = 1 + ring * segments, 1 + (ring + 1) * segments
        faces += [(a + s, b + s, b + (s + 1) % segments, a + (s + 1) % segments)
                  for s in range(segments)]
    last = 1 + (rings - 2) * segments
    faces += [(last + (s + 1) % segments, last + s, bottom) for s in range(segments)]
    obj = mesh_object(name, vertices, faces, material, smooth=True)
    obj.location = location
    return obj


# --- materials --------------------------------------------------------------------------------

class Nodes:
    """A material's node tree with short helpers for the few nodes the scenes use."""

    def __init__(self, material):
        material.use_nodes = True
        self.tree = material.node_tree
        self.tree.nodes.clear()
        self.output = self.tree.nodes.new('ShaderNodeOutputMaterial')

    def new(self, kind, **inputs):
        node = self.tree.nodes.new(kind)
        for key, value in inputs.items():
            if key in node.inputs and not hasattr(value, 'is_linked'):
                node.inputs[key].default_value = value
            elif hasattr(node, key):
                setattr(node, key, value)
            else:
                self.link(value, node.inputs[key])
        return node

    def link(self, socket, target):
        self.tree.links.new(socket, target)

    def object_coordinates(self, scale=1.0):
        """Object-space position scaled: texture coordinates that need no UV map."""
        coords = self.new('ShaderNodeTexCoord')
        mapping = self.new('ShaderNodeMapping')
        mapping.inputs['Scale'].default_value = (scale, scale, scale)
        self.link(coords.outputs['Object'], mapping.inputs['Vector'])
        return mapping.outputs['Vector']


def _no_light_sampling(material):
    # An emitting surface is not a light here: sampling it would add noise to lit surfaces.
    if hasattr(material.cycles, 'sample_as_light'):
        material.cycles.sample_as_light = False
    elif hasattr(material.cycles, 'emission_sampling'):
        material.cycles.emission_sampling = 'NONE'


def emission(name, color_socket_builder, strength=1.0):
    """An emission-only material whose colour comes from `color_socket_builder(nodes)`."""
    material = bpy.data.materials.new(name)
    nodes = Nodes(material)
    color = color_socket_builder(nodes)
    shader = nodes.new('ShaderNodeEmission', Strength=strength)
    if isinstance(color, tuple):
        shader.inputs['Color'].default_value = color
    else:
        nodes.link(color, shader.inputs['Color'])
    nodes.link(shader.outputs['Emission'], nodes.output.inputs['Surface'])
    _no_light_sampling(material)
    return material


def flat(color):
    return lambda nodes: color


def checker(color1, color2, scale):
    def build(nodes):
        tex = nodes.new('ShaderNodeTexChecker', Scale=1.0, Color1=color1, Color2=color2)
        nodes.link(nodes.object_coordinates(scale), tex.inputs['Vector'])
        return tex.outputs['Color']
    return build


def bricks(mortar, color1, color2, scale, brick_width=0.5, row_height=0.25):
    def build(nodes):
        tex = nodes.new('ShaderNodeTexBrick', Scale=1.0, Color1=color1, Color2=color2,
                        Mortar=mortar)
        tex.inputs['Brick Width'].default_value = brick_width
        tex.inputs['Row Height'].default_value = row_height
        tex.inputs['Mortar Size'].default_value = 0.015
        nodes.link(nodes.object_coordinates(scale), tex.inputs['Vector'])
        return tex.outputs['Color']
    return build


def stripes(color1, color2, scale, axis='X'):
    """Hard-edged bands: a wave texture through a constant colour ramp."""
    def build(nodes):
        wave = nodes.new('ShaderNodeTexWave', wave_type='BANDS', bands_direction=axis)
        wave.inputs['Scale'].default_value = 1.0
        nodes.link(nodes.object_coordinates(scale), wave.inputs['Vector'])
        ramp = nodes.new('ShaderNodeValToRGB')
        ramp.color_ramp.interpolation = 'CONSTANT'
        ramp.color_ramp.elements[0].color = color1
        ramp.color_ramp.elements[1].position = 0.5
        ramp.color_ramp.elements[1].color = color2
        nodes.link(wave.outputs['Fac'], ramp.inputs['Fac'])
        return ramp.outputs['Color']
    return build


def mix(factor_builder, a_builder, b_builder):
    """Colour b over colour a where the factor (a colour's first channel) is 1."""
    def build(nodes):
        mixer = nodes.new('ShaderNodeMixRGB', blend_type='MIX')
        nodes.link(factor_builder(nodes), mixer.inputs['Fac'])
        for slot, builder in ((1, a_builder), (2, b_builder)):
            value = builder(nodes)
            if isinstance(value, tuple):
                mixer.inputs[slot].default_value = value
            else:
                nodes.link(value, mixer.inputs[slot])
        return mixer.outputs['Color']
    return build


def world_position():
    """The shading point's world position as a colour (the conventions check reads it back)."""
    def build(nodes):
        return nodes.new('ShaderNodeNewGeometry').outputs['Position']
    return build


def lit(name, base_builder, roughness=0.5, metallic=0.0, specular=0.5):
    """A Principled BSDF surface lit by the scene's point lights (direct light only)."""
    material = bpy.data.materials.new(name)
    nodes = Nodes(material)
    shader = nodes.new('ShaderNodeBsdfPrincipled', Roughness=roughness, Metallic=metallic,
                       Specular=specular)
    base = base_builder(nodes)
    if isinstance(base, tuple):
        shader.inputs['Base Color'].default_value = base
    else:
        nodes.link(base, shader.inputs['Base Color'])
    nodes.link(shader.outputs['BSDF'], nodes.output.inputs['Surface'])
    return material


# --- world ------------------------------------------------------------------------------------

def world(zenith, horizon):
    """A sky gradient seen by the camera only: it lights nothing (no noise on lit surfaces)."""
    w = bpy.data.worlds.new('sky')
    w.use_nodes = True
    tree = w.node_tree
    tree.nodes.clear()
    out = tree.nodes.new('ShaderNodeOutputWorld')
    background = tree.nodes.new('ShaderNodeBackground')
    coords = tree.nodes.new('ShaderNodeTexCoord')
    split = tree.nodes.new('ShaderNodeSeparateXYZ')
    ramp = tree.nodes.new('ShaderNodeValToRGB')
    ramp.color_ramp.elements[0].color = horizon
    ramp.color_ramp.elements[1].position = 0.6
    ramp.color_ramp.elements[1].color = zenith
    tree.links.new(coords.outputs['Generated'], split.inputs['Vector'])
    tree.links.new(split.outputs['Z'], ramp.inputs['Fac'])
    tree.links.new(ramp.outputs['Color'], background.inputs['Color'])
    tree.links.new(background.outputs['Background'], out.inputs['Surface'])
    for ray in ('diffuse', 'glossy', 'transmission', 'scatter'):
        setattr(w.cycles_visibility, ray, False)
    if hasattr(w.cycles, 'sampling_method'):
        w.cycles.sampling_method = 'NONE'
    bpy.context.scene.world = w
    return w


def point_light(name, energy, color=(1, 1, 1)):
    """A point light of radius 0: hard shadows, no sampling noise."""
    data = bpy.data.lights.new(name, 'POINT')
    data.energy = energy
    data.color = color
    data.shadow_soft_size = 0.0
    obj = bpy.data.objects.new(name, data)
    bpy.context.scene.collection.objects.link(obj)
    return obj


# --- animation --------------------------------------------------------------------------------

def animate(obj, frames, transform):
    """Keys location and rotation at every frame from `transform(frame) -> (location, euler)`,
    linear between keys, so the motion between two frames is what the vectors describe."""
    for frame in frames:
        location, rotation = transform(frame)
        obj.location = location
        obj.rotation_euler = rotation
        obj.keyframe_insert('location', frame=frame)
        obj.keyframe_insert('rotation_euler', frame=frame)
    for curve in obj.animation_data.action.fcurves:
        for key in curve.keyframe_points:
            key.interpolation = 'LINEAR'


def look_rotation(yaw_degrees, pitch_degrees, roll_degrees=0.0):
    """Euler angles of a camera looking along +y turned by yaw (left +) and pitch (up +)."""
    return (math.radians(90.0 + pitch_degrees), math.radians(roll_degrees),
            math.radians(yaw_degrees))


def camera(lens_mm=35.0, sensor_mm=36.0, clip=(0.05, 500.0)):
    data = bpy.data.cameras.new('camera')
    data.lens = lens_mm
    data.sensor_width = sensor_mm
    data.sensor_fit = 'AUTO'
    data.clip_start, data.clip_end = clip
    obj = bpy.data.objects.new('camera', data)
    bpy.context.scene.collection.objects.link(obj)
    bpy.context.scene.camera = obj
    return obj
