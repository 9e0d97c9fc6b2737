// taatool's faster ZIP codec for OpenEXR. OpenEXR compresses and decompresses ZIP and ZIPS
// blocks (and DWA's zlib parts) with zlib's one-shot compress2() and uncompress(); these take
// half of taatool's CPU on a 1080p ZIP sequence. This unit defines both functions on top of
// libdeflate, which writes and reads the same zlib stream format two to three times faster.
// Linked into the taatool executable only: ELF symbol interposition makes the executable's
// definitions the ones every library in the process calls, so OpenEXR (through OIIO) uses them
// unchanged. It is not part of libtaa: a library must not replace its host's zlib.
// Anything libdeflate cannot do exactly as zlib would (level 0, a buffer too small, corrupt
// data) goes to zlib's own function, so results and errors keep zlib's behaviour.
#pragma once

#include <string>

namespace taa::fast_zlib {

// True when the process's compress2 and uncompress are this unit's (the interposition took).
bool active();

// One line for `taatool --info`: which codec serves zlib's one-shot calls.
std::string description();

}  // namespace taa::fast_zlib
