"""The jitter as a camera lens shift. Blender and Cycles measure the shift in units of the
sensor-fitted image side (for AUTO: the larger side, in pixels times the pixel aspect), so one
pixel of jitter is 1 / that side: shift_x = jx / side, shift_y = -jy * ycor / side (y up in
Blender, down in taa; ycor = pixel aspect y / x). Cycles places sample 0 of a pixel at its
centre, and the shift is not animated, so the Vector pass carries no jitter (both checked by
tests/blender)."""


def render_size(scene):
    """The rendered image's size in pixels, after the resolution percentage (Blender rounds
    down)."""
    render = scene.render
    return (render.resolution_x * render.resolution_percentage // 100,
            render.resolution_y * render.resolution_percentage // 100)


def shift_per_pixel(scene, camera_data):
    """(per_x, per_y): the lens shift that moves the image by one pixel right, one pixel up."""
    width, height = render_size(scene)
    aspect_x, aspect_y = scene.render.pixel_aspect_x, scene.render.pixel_aspect_y
    y_correction = aspect_y / aspect_x
    fit = camera_data.sensor_fit
    if fit == 'AUTO':
        horizontal = aspect_x * width >= aspect_y * height
    else:
        horizontal = fit == 'HORIZONTAL'
    side = float(width) if horizontal else y_correction * height
    return 1.0 / side, y_correction / side


def jittered_shift(scene, camera_data, base, jitter):
    """The lens shift (x, y) that moves `base`'s image by `jitter` pixels (x right, y down)."""
    per_x, per_y = shift_per_pixel(scene, camera_data)
    return base[0] + jitter[0] * per_x, base[1] - jitter[1] * per_y
