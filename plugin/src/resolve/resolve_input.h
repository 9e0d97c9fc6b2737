// What both resolvers (history: resolve/resolver, window: resolve/window_resolver) ask of the
// planes a frame brings, and how its samples' type reaches the GL.
#pragma once

#include "gl/gl_functions.h"
#include "util/image.h"

namespace taa {

// A depth or motion plane (`name`; absent is fine) must be the colour's size with `channels`
// channels; the Error names the plane as its channel.
void checkPlane(const ImageView& plane, const ImageView& color, int channels, const char* name);

// The GL type of a plane's samples.
GLenum glType(SampleType type);

}  // namespace taa
