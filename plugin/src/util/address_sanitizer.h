// TAA_ADDRESS_SANITIZER: 1 in a build with AddressSanitizer (GCC defines __SANITIZE_ADDRESS__,
// Clang answers __has_feature), else 0. One definition for the code that changes under it and
// the tests that follow it.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define TAA_ADDRESS_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TAA_ADDRESS_SANITIZER 1
#endif
#endif
#ifndef TAA_ADDRESS_SANITIZER
#define TAA_ADDRESS_SANITIZER 0
#endif
