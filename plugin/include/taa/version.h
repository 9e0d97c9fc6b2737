// taa's version. The C++ API lives in a versioned inline namespace so that two builds with
// incompatible layouts cannot be mixed silently; the C ABI (taa.h) has its own integer version.
#pragma once

#define TAA_VERSION_MAJOR 0
#define TAA_VERSION_MINOR 1
#define TAA_VERSION_PATCH 0
#define TAA_VERSION_STRING "0.1.0"

#define TAA_NAMESPACE_BEGIN \
  namespace taa {           \
  inline namespace v0 {
#define TAA_NAMESPACE_END \
  }                       \
  }
