#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "gl/objects.h"
#include "gl/shader_expansion.h"
#include "gl/shader_library.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::StartsWith;

// A lookup over in-memory files, standing in for the embedded glsl/ folder.
ShaderLookup filesLookup(const std::map<std::string, std::string>& files) {
  return [&files](const std::string& name) -> const char* {
    auto found = files.find(name);
    return found == files.end() ? nullptr : found->second.c_str();
  };
}

std::string expectError(const std::function<void()>& action) {
  try {
    action();
  } catch (const Error& error) {
    return error.what();
  }
  ADD_FAILURE() << "no taa::Error thrown";
  return {};
}

TEST(ShaderExpansion, ExpandsNestedIncludesOnceWithLineDirectives) {
  const std::map<std::string, std::string> files = {
      {"main.frag", "#version 410 core\n// main\n#include \"a.glsl\"\nvoid main() {}\n"},
      {"a.glsl", "// a\n#include \"b.glsl\"\nfloat a() { return b(); }\n"},
      {"b.glsl", "#include \"a.glsl\"\nfloat b() { return 1.0; }\n"},
  };
  std::vector<std::string> names;
  const std::string source = expandShaderIncludes("main.frag", filesLookup(files), &names);
  EXPECT_EQ(source,
            "#version 410 core\n"
            "#line 1 0\n"
            "\n"  // the #version line itself, blanked
            "// main\n"
            "#line 1 1\n"
            "// a\n"
            "#line 1 2\n"
            "// #include \"a.glsl\" (already included)\n"
            "float b() { return 1.0; }\n"
            "#line 3 1\n"
            "float a() { return b(); }\n"
            "#line 4 0\n"
            "void main() {}\n");
  EXPECT_THAT(names, ElementsAre("main.frag", "a.glsl", "b.glsl"));
}

TEST(ShaderExpansion, MovesALaterVersionLineToTheTop) {
  const std::map<std::string, std::string> files = {
      {"main.frag", "// header comment\n#version 410 core\nvoid main() {}\n"}};
  EXPECT_EQ(expandShaderIncludes("main.frag", filesLookup(files), nullptr),
            "#version 410 core\n#line 1 0\n// header comment\n\nvoid main() {}\n");
}

TEST(ShaderExpansion, ReportsUnknownIncludeWithFileAndLine) {
  const std::map<std::string, std::string> files = {
      {"main.frag", "#version 410 core\n\n#include \"missing.glsl\"\n"}};
  EXPECT_THAT(expectError([&] { expandShaderIncludes("main.frag", filesLookup(files), nullptr); }),
              HasSubstr("main.frag:3: #include of unknown shader file \"missing.glsl\""));
}

TEST(ShaderExpansion, RejectsMalformedIncludeAndMisplacedVersion) {
  const std::map<std::string, std::string> files = {
      {"angle.frag", "#version 410 core\n#include <a.glsl>\n"},
      {"noversion.frag", "void main() {}\n"},
      {"nested.frag", "#version 410 core\n#include \"v.glsl\"\n"},
      {"v.glsl", "#version 330 core\n"},
  };
  const ShaderLookup lookup = filesLookup(files);
  EXPECT_THAT(expectError([&] { expandShaderIncludes("angle.frag", lookup, nullptr); }),
              HasSubstr("angle.frag:2: malformed #include"));
  EXPECT_THAT(expectError([&] { expandShaderIncludes("noversion.frag", lookup, nullptr); }),
              HasSubstr("\"noversion.frag\" has no #version line"));
  EXPECT_THAT(expectError([&] { expandShaderIncludes("nested.frag", lookup, nullptr); }),
              HasSubstr("v.glsl:1: #version is only allowed in the top-level shader"));
}

TEST(ShaderExpansion, InsertsDefinesAfterTheVersionLine) {
  EXPECT_EQ(insertAfterFirstLine("#version 410 core\n#line 1 0\nx\n", {"#define A 1", "#define B"}),
            "#version 410 core\n#define A 1\n#define B\n#line 1 0\nx\n");
  EXPECT_EQ(insertAfterFirstLine("#version 410 core\nx\n", {}), "#version 410 core\nx\n");
  // #extension lines must precede any code, defines (or generated functions) included.
  EXPECT_EQ(insertAfterFirstLine("#version 410 core\n#extension GL_X : require\n#line 1 0\nx\n",
                                 {"#define A 1"}),
            "#version 410 core\n#extension GL_X : require\n#define A 1\n#line 1 0\nx\n");
}

// Extensions from any file go up to just after #version, once each; their lines stay, blank,
// so the driver's line numbers still name the right file lines.
TEST(ShaderExpansion, HoistsExtensionLinesAfterTheVersion) {
  const std::map<std::string, std::string> files = {
      {"main.frag", "#version 410 core\n#include \"a.glsl\"\nvoid main() {}\n"},
      {"a.glsl", "#extension GL_X : require\nint a;\n#extension GL_X : require\n"},
  };
  std::vector<std::string> names;
  EXPECT_EQ(expandShaderIncludes("main.frag", filesLookup(files), &names),
            "#version 410 core\n#extension GL_X : require\n#line 1 0\n\n#line 1 1\n\nint a;\n"
            "\n#line 3 0\nvoid main() {}\n");
}

TEST(ShaderExpansion, AnnotatesMesaAndNvidiaLogsWithFileLines) {
  const std::string source =
      "#version 410 core\n#line 1 0\n\nvoid main() {\n#line 1 1\nfloat f() { oops; }\n"
      "#line 3 0\n  bad;\n}\n";
  const std::vector<std::string> names = {"main.frag", "helper.glsl"};
  const std::string mesa = annotateShaderLog("1:1(13): error: `oops' undeclared\n"
                                             "0:3(3): error: `bad' undeclared\n",
                                             source, names);
  EXPECT_THAT(mesa, HasSubstr("source strings: 0 = main.frag, 1 = helper.glsl"));
  EXPECT_THAT(mesa, HasSubstr("helper.glsl:1: float f() { oops; }"));
  EXPECT_THAT(mesa, HasSubstr("main.frag:3:   bad;"));
  const std::string nvidia = annotateShaderLog("1(1) : error C1008: undefined variable \"oops\"",
                                               source, names);
  EXPECT_THAT(nvidia, HasSubstr("helper.glsl:1: float f() { oops; }"));
}

TEST(EmbeddedShaders, PatternAndFullscreenAreEmbeddedWithVersionFirst) {
  std::vector<std::string> names;
  const std::string pattern = expandedShaderSource("pattern.frag", &names);
  EXPECT_THAT(pattern, StartsWith("#version 410 core\n#line 1 0\n"));
  EXPECT_THAT(names, ElementsAre("pattern.frag"));
  const ShaderSource vertex = embeddedShaderSource("fullscreen.vert", {"#define X 2"});
  EXPECT_THAT(vertex.text, StartsWith("#version 410 core\n#define X 2\n#line 1 0\n"));
  EXPECT_THAT(vertex.fileNames, ElementsAre("fullscreen.vert"));
  EXPECT_THAT(expectError([] { expandedShaderSource("no_such.frag", nullptr); }),
              HasSubstr("unknown embedded shader \"no_such.frag\""));
}

}  // namespace
}  // namespace taa::gl
