#include <gtest/gtest.h>

#include "gl/context.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

TEST(ParseBackend, AcceptsTheThreeNames) {
  EXPECT_EQ(parseBackend("auto"), Backend::Auto);
  EXPECT_EQ(parseBackend("egl"), Backend::Egl);
  EXPECT_EQ(parseBackend("osmesa"), Backend::OsMesa);
}

TEST(ParseBackend, NamesRoundTrip) {
  for (Backend backend : {Backend::Auto, Backend::Egl, Backend::OsMesa}) {
    EXPECT_EQ(parseBackend(backendName(backend)), backend);
  }
}

TEST(ParseBackend, RejectsUnknownNameWithTheChoices) {
  try {
    parseBackend("foo");
    FAIL() << "parseBackend(\"foo\") did not throw";
  } catch (const Error& error) {
    EXPECT_EQ(error.description(), "unknown GL back end \"foo\" (expected auto, egl or osmesa)");
  }
  EXPECT_THROW(parseBackend("EGL"), Error);  // names are lower case, as on the command line
  EXPECT_THROW(parseBackend(""), Error);
}

}  // namespace
}  // namespace taa::gl
