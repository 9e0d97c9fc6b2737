#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "gl/dynamic_library.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

using ::testing::HasSubstr;

TEST(DynamicLibrary, MissingLibraryErrorNamesEveryCandidateAndTheReason) {
  try {
    DynamicLibrary::open({"libtaa_missing_test.so.1", "libtaa_missing_test.so"});
    FAIL() << "opening a library that does not exist did not throw";
  } catch (const Error& error) {
    const std::string message = error.what();
    EXPECT_THAT(message, HasSubstr("cannot load libtaa_missing_test.so.1, libtaa_missing_test.so"));
    EXPECT_THAT(message, HasSubstr("cannot open shared object file"));  // dlerror's reason
  }
}

TEST(DynamicLibrary, NoCandidatesIsAnError) {
  EXPECT_THROW(DynamicLibrary::open({}), Error);
}

TEST(DynamicLibrary, FallsBackToALaterCandidateAndFindsSymbols) {
  DynamicLibrary library = DynamicLibrary::open({"libtaa_missing_test.so", "libc.so.6"});
  ASSERT_TRUE(library);
  EXPECT_EQ(library.name(), "libc.so.6");
  using StrlenFn = size_t (*)(const char*);
  EXPECT_EQ(library.function<StrlenFn>("strlen")("taa"), 3u);
  EXPECT_EQ(library.symbol("taa_no_such_symbol"), nullptr);
  try {
    library.requireSymbol("taa_no_such_symbol");
    FAIL() << "a missing symbol did not throw";
  } catch (const Error& error) {
    EXPECT_THAT(std::string(error.what()), HasSubstr("taa_no_such_symbol"));
    EXPECT_THAT(std::string(error.what()), HasSubstr("libc.so.6"));
  }
}

TEST(DynamicLibrary, MovesOwnership) {
  DynamicLibrary first = DynamicLibrary::open({"libc.so.6"});
  DynamicLibrary second = std::move(first);
  EXPECT_FALSE(first);  // NOLINT(bugprone-use-after-move): checking the moved-from state
  EXPECT_TRUE(second);
  EXPECT_NE(second.symbol("strlen"), nullptr);
  DynamicLibrary third;
  third = std::move(second);
  EXPECT_TRUE(third);
  EXPECT_FALSE(second);  // NOLINT(bugprone-use-after-move)
}

}  // namespace
}  // namespace taa::gl
