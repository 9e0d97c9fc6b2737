// taa's camera note: a frame's camera and jitter in its colour header, as the string attribute
// "Note" (Blender's stamp note reaches a multilayer EXR's header under that name; the add-on in
// plugin/blender writes it per frame). Format (docs/ARCHITECTURE.md, "Camera note"):
//   taa-camera/1 {"view":[16 numbers],"projection":[16 numbers],"jitter":[jx,jy]}
// the prefix, one space, then one camera sidecar entry (io/camera_sidecar.h): OpenGL view and
// unjittered projection listed column by column, the jitter in pixels, x right, y down.
// A Note without the "taa-camera/" prefix is someone else's and is ignored.
#pragma once

#include <OpenImageIO/imageio.h>

#include <optional>
#include <string>

#include "io/camera_sidecar.h"
#include "taa/error.h"

namespace taa::io {

inline constexpr const char* kCameraNoteAttribute = "Note";
inline constexpr const char* kCameraNoteFamily = "taa-camera/";  // any version of the note
inline constexpr const char* kCameraNoteVersion = "taa-camera/1";  // the version read here

// True when `text` claims to be a camera note (any version).
bool isCameraNote(const std::string& text);

// The note's entry. Throws taa::Error with `context` (its channel set to "Note") for another
// version of the note, malformed JSON after the prefix or a malformed entry (wrong lengths,
// non-numbers, a jitter beyond float's range).
SidecarFrame parseCameraNote(const std::string& text, ErrorContext context);

// The camera note of a colour header: nullopt when the header has no string "Note" or it is
// not a camera note. Errors as parseCameraNote's, naming `path` and `frame`.
std::optional<SidecarFrame> readCameraNote(const OIIO::ImageSpec& header, const std::string& path,
                                           int frame);

}  // namespace taa::io
