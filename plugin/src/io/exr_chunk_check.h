// A header whose data window is wider than the pixels stored (a damaged or hand-edited file)
// reads as zeros through OpenEXR's C++ reader, without an error (issue 25). OpenEXR's core
// library checks a chunk's size against the window: one chunk a part is decoded with it before
// the frame is read, so such a file is refused at the cost of a few scanlines.
#pragma once

#include <string>

namespace taa::io {

// "" when the first chunk of every scanline part of `path` holds the bytes its data window
// asks for (tiled parts are not checked); otherwise why not, for a message.
std::string firstChunkMismatch(const std::string& path);

}  // namespace taa::io
