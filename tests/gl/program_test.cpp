#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <map>
#include <string>
#include <vector>

#include "gl/context.h"
#include "gl/objects.h"
#include "gl/shader_expansion.h"
#include "gl_test_support.h"
#include "taa/error.h"

namespace taa::gl {
namespace {

using ::testing::HasSubstr;

class ProgramTest : public ::testing::TestWithParam<Backend> {
 protected:
  void SetUp() override { context_ = Context::create(GetParam()); }
  const Functions& gl() const { return context_->functions(); }

  // The message of the taa::Error that building the program throws.
  std::string buildError(const ShaderSource& vertex, const ShaderSource& fragment) {
    try {
      Program program(gl(), vertex, fragment);
    } catch (const Error& error) {
      return error.what();
    }
    ADD_FAILURE() << "the program built without error";
    return {};
  }

  std::unique_ptr<Context> context_;
};

TEST_P(ProgramTest, CompileErrorNamesTheShaderAndQuotesTheDriverLog) {
  const ShaderSource broken = test::fragmentShader(
      "broken_test.frag", "void main() {\n  outColor = vec4(undeclaredThing);\n}\n");
  const std::string message = buildError(embeddedShaderSource("fullscreen.vert"), broken);
  EXPECT_THAT(message, HasSubstr("fragment shader \"broken_test.frag\" failed to compile"));
  EXPECT_THAT(message, HasSubstr("undeclaredThing"));  // from the driver's log
  EXPECT_THAT(message, HasSubstr("error"));
  EXPECT_THAT(message, HasSubstr("source strings: 0 = broken_test.frag"));
  EXPECT_THAT(message, HasSubstr("broken_test.frag:4:   outColor = vec4(undeclaredThing);"));
}

TEST_P(ProgramTest, ErrorsInIncludedFilesPointAtTheIncludedFileAndLine) {
  // Checks the #line directives against the real driver: the log must name helper.glsl:3.
  const std::map<std::string, std::string> files = {
      {"main.frag",
       "#version 410 core\nlayout(location = 0) out vec4 outColor;\n#include \"helper.glsl\"\n"
       "void main() { outColor = vec4(helper()); }\n"},
      {"helper.glsl", "// a helper\n\nfloat helper() { return missingName; }\n"},
  };
  ShaderSource fragment{"main.frag", "", {}};
  fragment.text = expandShaderIncludes(
      "main.frag",
      [&](const std::string& name) -> const char* {
        auto found = files.find(name);
        return found == files.end() ? nullptr : found->second.c_str();
      },
      &fragment.fileNames);
  const std::string message = buildError(embeddedShaderSource("fullscreen.vert"), fragment);
  EXPECT_THAT(message, HasSubstr("missingName"));
  EXPECT_THAT(message, HasSubstr("source strings: 0 = main.frag, 1 = helper.glsl"));
  EXPECT_THAT(message, HasSubstr("helper.glsl:3: float helper() { return missingName; }"));
}

TEST_P(ProgramTest, VertexCompileErrorIsReportedAsVertex) {
  const ShaderSource vertex{"broken_test.vert", "#version 410 core\nvoid main() { nope(); }\n", {}};
  const std::string message =
      buildError(vertex, test::fragmentShader("ok.frag", "void main() { outColor = vec4(1); }"));
  EXPECT_THAT(message, HasSubstr("vertex shader \"broken_test.vert\" failed to compile"));
}

TEST_P(ProgramTest, LinkErrorNamesBothShaders) {
  // A function declared but defined in no stage compiles, and fails only at link time.
  const ShaderSource fragment = test::fragmentShader(
      "unresolved.frag", "float notDefinedAnywhere();\n"
                         "void main() { outColor = vec4(notDefinedAnywhere()); }\n");
  const std::string message = buildError(embeddedShaderSource("fullscreen.vert"), fragment);
  EXPECT_THAT(message, HasSubstr("program \"fullscreen.vert + unresolved.frag\" failed to link"));
  EXPECT_THAT(message, HasSubstr("notDefinedAnywhere"));  // from the driver's log
}

TEST_P(ProgramTest, EmbeddedProgramsTakeDefines) {
  const ShaderSource fragment = test::fragmentShader(
      "define.frag", "void main() { outColor = vec4(VALUE); }\n");
  ShaderSource withDefine = fragment;
  withDefine.text = insertAfterFirstLine(fragment.text, {"#define VALUE 2.5"});
  EXPECT_EQ(test::renderPass(gl(), withDefine, 1, 1)[0], 2.5f);
  EXPECT_THROW(test::renderPass(gl(), fragment, 1, 1), Error);  // VALUE undefined
  // The embedded-name constructor passes defines to both stages.
  EXPECT_NO_THROW(Program(gl(), "fullscreen.vert", "pattern.frag", {"#define UNUSED 1"}));
  EXPECT_THROW(Program(gl(), "fullscreen.vert", "no_such.frag"), Error);
}

TEST_P(ProgramTest, UniformSettersReachTheShader) {
  const ShaderSource fragment = test::fragmentShader(
      "uniforms.frag",
      "uniform int uInt;\nuniform float uFloat;\nuniform vec2 uVec2;\nuniform vec4 uVec4;\n"
      "uniform mat4 uMatrix;\n"
      "void main() {\n"
      "  outColor = vec4(float(uInt), uFloat, uVec2) + uVec4 + uMatrix * vec4(1, 2, 3, 4);\n"
      "}\n");
  // Column-major: column k is (k, 0, 0, 0) + 10 * (0, 1, 0, 0) for k = 0..3.
  const float matrix[16] = {0, 10, 0, 0, 1, 10, 0, 0, 2, 10, 0, 0, 3, 10, 0, 0};
  const std::vector<float> pixels = test::renderPass(gl(), fragment, 2, 2, [&](const Program& p) {
    p.set("uInt", 7);
    p.set("uFloat", 0.25f);
    p.set("uVec2", -3.0f, 4.5f);
    p.set("uVec4", 100.0f, 200.0f, 300.0f, 400.0f);
    p.setMatrix4("uMatrix", matrix);
    p.set("uNotInTheShader", 1.0f);  // ignored, as GL ignores location -1
  });
  // matrix * (1,2,3,4) = (0*1 + 1*2 + 2*3 + 3*4, 10 * 10, 0, 0) = (20, 100, 0, 0).
  const float expected[4] = {7 + 100 + 20, 0.25f + 200 + 100, -3 + 300, 4.5f + 400};
  for (int c = 0; c < 4; ++c) EXPECT_EQ(pixels[12 + c], expected[c]) << "channel " << c;
}

INSTANTIATE_TEST_SUITE_P(Backends, ProgramTest, ::testing::Values(Backend::Egl, Backend::OsMesa),
                         test::backendParamName);

}  // namespace
}  // namespace taa::gl
