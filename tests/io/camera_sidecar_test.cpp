// The JSON camera sidecar: conversion of OpenGL matrices, jitter, and clear errors.
#include "io/camera_sidecar.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>
#include <glm/vec4.hpp>

#include <functional>

#include "taa/error.h"
#include "test_files.h"

namespace taa::io {
namespace {

using taa::test::contains;
using taa::test::errorOf;
using taa::test::scratchFolder;
using taa::test::writeTextFile;

std::string numbers(const glm::dmat4& m) {
  std::string text = "[";
  for (int column = 0; column < 4; ++column) {
    for (int row = 0; row < 4; ++row) {
      text += (column + row == 0 ? "" : ", ") + std::to_string(m[column][row]);
    }
  }
  return text + "]";
}

TEST(CameraSidecar, OpenGlMatricesBecomeAPlusZForwardCameraAndJitterIsKept) {
  const std::string path = scratchFolder() + "/camera.json";
  // Camera at (0, 0, 10) looking at the origin (down world -z), 60 degree vertical fov.
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0, 0, 10), glm::dvec3(0), glm::dvec3(0, 1, 0));
  const glm::dmat4 projection = glm::perspective(glm::radians(60.0), 2.0, 0.1, 1000.0);
  writeTextFile(path, R"({"frames": {"7": {"view": )" + numbers(view) +
                          R"(, "projection": )" + numbers(projection) +
                          R"(, "jitter": [0.25, -0.125]}, "8": {"jitter": [0, 0]}}})");
  const CameraSidecar sidecar = CameraSidecar::load(path);
  const FrameCamera& camera = sidecar.camera(7);
  // The world origin is 10 units in front of the camera: +10 on the camera's z axis.
  const glm::dvec4 origin = camera.worldToCamera * glm::dvec4(0, 0, 0, 1);
  EXPECT_NEAR(origin.z, 10.0, 1e-5);
  // ... and at the centre of OpenGL's NDC.
  const glm::dvec4 ndc = camera.worldToNdc * glm::dvec4(0, 0, 0, 1);
  EXPECT_NEAR(ndc.x / ndc.w, 0.0, 1e-6);
  EXPECT_NEAR(ndc.y / ndc.w, 0.0, 1e-6);
  // A point above the axis is up in NDC (y up).
  const glm::dvec4 up = camera.worldToNdc * glm::dvec4(0, 1, 0, 1);
  EXPECT_GT(up.y / up.w, 0.0);
  EXPECT_EQ(sidecar.jitter(7), glm::vec2(0.25f, -0.125f));
  EXPECT_EQ(sidecar.jitter(8), glm::vec2(0.0f));
  EXPECT_EQ(CameraSidecar::kNdc, NdcConvention::MinusOneOneYUp);
}

TEST(CameraSidecar, MissingFrameNamesFileAndFrame) {
  const std::string path = scratchFolder() + "/camera.json";
  writeTextFile(path, R"({"frames": {"1": {"jitter": [0.1, 0.2]}}})");
  const CameraSidecar sidecar = CameraSidecar::load(path);
  const Error missing = errorOf([&] { sidecar.frame(2); });
  EXPECT_TRUE(contains(missing.what(), "no entry")) << missing.what();
  EXPECT_EQ(missing.context().file, path);
  EXPECT_EQ(missing.context().frame, 2);
  const Error noMatrices = errorOf([&] { sidecar.camera(1); });
  EXPECT_TRUE(contains(noMatrices.what(), "view/projection")) << noMatrices.what();
  EXPECT_EQ(noMatrices.context().frame, 1);
}

TEST(CameraSidecar, UnreadableOrMalformedFilesAreErrorsNamingTheFile) {
  const std::string folder = scratchFolder();
  const Error absent = errorOf([&] { CameraSidecar::load(folder + "/none.json"); });
  EXPECT_TRUE(contains(absent.what(), "cannot read the camera sidecar")) << absent.what();
  EXPECT_EQ(absent.context().file, folder + "/none.json");

  const std::vector<std::pair<std::string, std::string>> bad = {
      {"{\"frames\": {\"1\": {\"jitter\": [0.1,", "not valid JSON"},
      {"[1, 2, 3]", "no \"frames\" object"},
      {R"({"frames": {"one": {}}})", "not a frame number"},
      {R"({"frames": {"3": {"view": [1, 2, 3], "projection": [1]}}})", "16 numbers"},
      {R"({"frames": {"3": {"view": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}}})", "both"},
      {R"({"frames": {"3": {"jitter": "left"}}})", "jitter"},
      // Issue 17: a jitter beyond float's range (JSON has no NaN or Inf; nlohmann refuses
      // doubles that overflow) made the frame +Inf.
      {R"({"frames": {"3": {"jitter": [1e39, 0]}}})", "jitter (inf, 0) from the camera sidecar is not a finite"},
      {R"({"frames": {"3": {"jitter": [0, -3.5e38]}}})", "not a finite number of pixels"},
      // Issue 25: 1e38 (finite) and 1e300 matrix entries were taken.
      {R"({"frames": {"3": {"jitter": [1e38, 0]}}})", "more than 1 pixel from the pixel centre"},
      {R"({"frames": {"3": {"view": [1e300,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1],
                              "projection": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}}})",
       "\"view\" holds 1000000"},
      {"{\"frames\": " + std::string(100000, '[') + std::string(100000, ']') + "}",
       "the camera sidecar nests deeper than 16 levels"},
  };
  for (const auto& [text, message] : bad) {
    const std::string path = folder + "/bad.json";
    writeTextFile(path, text);
    const Error error = errorOf([&] { CameraSidecar::load(path); });
    EXPECT_TRUE(contains(error.what(), message)) << text << " -> " << error.what();
    EXPECT_EQ(error.context().file, path) << text;
  }
}

}  // namespace
}  // namespace taa::io
