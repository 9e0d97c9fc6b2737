// Enum fields a host fills in (taa.h's taa_pixel_type, taa_gl_backend) may hold any integer: C
// allows it, and hosts make mistakes. Reading one outside the enumerators' range as the C++ enum
// is undefined behaviour (UBSan reports it), so the C ABI reads the stored int and compares that.
#pragma once

#include <cstring>

namespace taa::capi {

template <typename Enum>
int hostEnumValue(const Enum& field) {
  static_assert(sizeof(Enum) == sizeof(int), "taa.h's enums are int-sized");
  int value = 0;
  std::memcpy(&value, &field, sizeof value);
  return value;
}

}  // namespace taa::capi
