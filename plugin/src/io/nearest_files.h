// What a search for a pattern's files looked at and the names nearest to it: the error of a
// pattern that matches nothing says both, so a typo ("render.####.exr" for render_####.exr) or
// the wrong folder shows at once.
#pragma once

#include <string>

namespace taa::io {

// One clause for an error message about `pattern` (a frame pattern or a single file) that
// matched no file: where it looked and for what, then the files there whose names are nearest
// to it, a sequence of them collapsed to its first and last name and count:
//   looked in /shots/sh010 for names like render.0001.exr (#### = the frame number); nearest
//   there: render_0001.exr .. render_0024.exr (24 files), render.json
// Or that the folder does not exist (naming the nearest folder above that does), or is empty.
std::string patternMissText(const std::string& pattern);

}  // namespace taa::io
