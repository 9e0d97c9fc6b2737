// `taatool --info`: what taatool runs on.
#pragma once

#include <ostream>

#include "gl/context.h"

namespace taa::cli {

// Prints taa's version, the chosen GL back end's vendor/renderer/version (after a render
// self-test), and the OpenColorIO and OpenImageIO versions. Returns the exit status: 0 when the
// context works, 1 when its self-test fails. Context creation failures throw taa::Error.
int printInfo(gl::Backend backend, const gl::LogSink& log, std::ostream& out);

// Prints the active OCIO config (the path, $OCIO or the shipped one) and the brackets it offers,
// one per line. Throws taa::Error for an unreadable config.
void printBrackets(const std::string& ocioConfig, std::ostream& out);

}  // namespace taa::cli
