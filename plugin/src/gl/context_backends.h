// Internal to gl/: the back-end factories Context::create chooses from, and the checks and
// queries every back end runs once its context is current.
#pragma once

#include <memory>
#include <string>

#include "gl/context.h"

namespace taa::gl {

// Each throws taa::Error naming the back end, the step that failed and the native error.
std::unique_ptr<Context> createEglContext();
std::unique_ptr<Context> createOsMesaContext();

// Reads the strings of the current context into an info record and checks that it really is
// OpenGL 4.1 or newer (drivers may hand out less than asked for). Throws taa::Error otherwise.
ContextInfo queryContextInfo(const Functions& gl, Backend backend, const std::string& platform);

// True if the space-separated extension list `extensions` contains `name` as a whole word.
bool hasExtension(const char* extensions, const char* name);

}  // namespace taa::gl
