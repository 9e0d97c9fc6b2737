// What a host can ask libtaa about itself.
#pragma once

#include "taa/export.h"
#include "taa/version.h"

TAA_NAMESPACE_BEGIN

// The version of the loaded library, e.g. "0.1.0" (may differ from the header's
// TAA_VERSION_STRING if the host was built against another release).
TAA_API const char* libraryVersion();

TAA_NAMESPACE_END
