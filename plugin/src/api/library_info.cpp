// Exported entry points of libtaa.so that identify the library to a host.
#include "taa/library_info.h"

TAA_NAMESPACE_BEGIN

const char* libraryVersion() { return TAA_VERSION_STRING; }

TAA_NAMESPACE_END
