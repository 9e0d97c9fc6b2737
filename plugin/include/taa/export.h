// Symbol visibility for libtaa: everything is hidden unless marked TAA_API.
#pragma once

#if defined(TAA_BUILDING_LIBRARY)
#define TAA_API __attribute__((visibility("default")))
#else
#define TAA_API
#endif
