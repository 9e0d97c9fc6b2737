// The camera note in an EXR header (io/camera_note.h): the same numbers as a sidecar entry give
// the same camera and jitter, another Note is ignored, a bad note is an error naming file,
// frame and "Note"; readFrame takes the note's camera after the sidecar's and before the
// header's matrices.
#include "io/camera_note.h"

#include <gtest/gtest.h>

#include <vector>

#include "io/frame_reader.h"
#include "taa/error.h"
#include "test_files.h"

namespace taa::io {
namespace {

using taa::test::contains;
using taa::test::errorOf;
using taa::test::makeSpec;
using taa::test::scratchFolder;
using taa::test::writeImage;
using taa::test::writeTextFile;

// A camera at (0, 0, 5) looking down -z, and a perspective projection: numbers as the Blender
// add-on writes them (shortest text of float32 values).
const std::string kEntry =
    R"({"view":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,-5,1],)"
    R"("projection":[2.7777777,0,0,0,0,4.9382715,0,0,0.0123,-0.5,-1.0002,-1,0,0,-0.20002,0],)"
    R"("jitter":[0.16666669,-0.2777778]})";
const std::string kNote = "taa-camera/1 " + kEntry;

void expectSameMatrix(const glm::dmat4& a, const glm::dmat4& b) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) EXPECT_EQ(a[c][r], b[c][r]) << "column " << c << ", row " << r;
  }
}

TEST(CameraNote, GivesTheCameraAndJitterOfTheSameSidecarEntryBitForBit) {
  const std::string path = scratchFolder() + "/camera.json";
  writeTextFile(path, R"({"frames": {"12": )" + kEntry + "}}");
  const CameraSidecar sidecar = CameraSidecar::load(path);
  const SidecarFrame note = parseCameraNote(kNote, {"f.exr", 12, ""});
  ASSERT_TRUE(note.camera.has_value());
  ASSERT_TRUE(note.jitter.has_value());
  expectSameMatrix(note.camera->worldToCamera, sidecar.camera(12).worldToCamera);
  expectSameMatrix(note.camera->worldToNdc, sidecar.camera(12).worldToNdc);
  EXPECT_EQ(*note.jitter, sidecar.jitter(12));
  EXPECT_EQ(*note.jitter, glm::vec2(0.16666669f, -0.2777778f));
  // +z forward: the world origin is 5 in front of the camera.
  EXPECT_DOUBLE_EQ((note.camera->worldToCamera * glm::dvec4(0, 0, 0, 1)).z, 5.0);
}

TEST(CameraNote, OnlyNotesWithTheFamilyPrefixAreCameraNotes) {
  EXPECT_TRUE(isCameraNote(kNote));
  EXPECT_TRUE(isCameraNote("taa-camera/7 {}"));
  EXPECT_FALSE(isCameraNote("shot 12, take 3"));
  EXPECT_FALSE(isCameraNote(""));
  EXPECT_FALSE(isCameraNote(" taa-camera/1 {}"));
}

TEST(CameraNote, AHeaderWithoutNoteOrWithAnotherNoteHasNone) {
  OIIO::ImageSpec header = makeSpec(2, 2, {"R", "G", "B", "A"});
  EXPECT_FALSE(readCameraNote(header, "f.exr", 1).has_value());
  header.attribute("Note", "lighting pass v3");
  EXPECT_FALSE(readCameraNote(header, "f.exr", 1).has_value());
  header.attribute("Note", kNote);
  EXPECT_TRUE(readCameraNote(header, "f.exr", 1).has_value());
}

TEST(CameraNote, AJitterOnlyNoteHasNoCamera) {
  const SidecarFrame note = parseCameraNote(R"(taa-camera/1 {"jitter":[0.25,0]})", {});
  EXPECT_FALSE(note.camera.has_value());
  EXPECT_EQ(note.jitter, glm::vec2(0.25f, 0.0f));
}

TEST(CameraNote, BadNotesAreErrorsNamingFileFrameAndNote) {
  const std::vector<std::pair<std::string, std::string>> bad = {
      {"taa-camera/2 " + kEntry,
       "camera note is \"taa-camera/2\"; this taa reads \"taa-camera/1\""},
      {"taa-camera/1", "no entry after \"taa-camera/1\""},
      {"taa-camera/1 {\"view\":[1,0,0", "the header's camera note is not valid JSON"},
      {"taa-camera/1 " + kEntry.substr(0, kEntry.size() - 9), "not valid JSON"},  // cut short
      {R"(taa-camera/1 {"jitter":[NaN,0]})", "not valid JSON"},     // JSON has no NaN
      {R"(taa-camera/1 {"view":[1,0,0,1],"projection":[1]})", "\"view\" must be an array of 16"},
      {R"(taa-camera/1 {"view":[1,0,0,0,0,1,0,0,0,0,1,0,0,0,0,1]})", "both"},
      {R"(taa-camera/1 {"jitter":[0.1]})", "camera note entry \"jitter\" must be [jx, jy]"},
      {R"(taa-camera/1 {"jitter":[0.1,"x"]})", "\"jitter\" must be [jx, jy]"},
      {R"(taa-camera/1 {"jitter":[1e39,0]})",
       "jitter (inf, 0) from the header's camera note is not a finite number of pixels"},
      {"taa-camera/1 [1,2]", "camera note entry must be an object"},
  };
  for (const auto& [text, message] : bad) {
    OIIO::ImageSpec header = makeSpec(2, 2, {"R", "G", "B", "A"});
    header.attribute("Note", text);
    const Error error = errorOf([&] { readCameraNote(header, "/shot/f.0042.exr", 42); });
    EXPECT_TRUE(contains(error.description(), message)) << text << " -> " << error.what();
    EXPECT_EQ(error.context().file, "/shot/f.0042.exr") << text;
    EXPECT_EQ(error.context().frame, 42) << text;
    EXPECT_EQ(error.context().channel, "Note") << text;
  }
}

// A 2x2 RGBA file whose header holds `note` (none when empty) and, when asked, an identity
// worldToCamera/worldToNDC.
std::string writeFrame(const std::string& folder, const std::string& note,
                       bool headerMatrices = false) {
  OIIO::ImageSpec spec = makeSpec(2, 2, {"R", "G", "B", "A"});
  if (!note.empty()) spec.attribute("Note", note);
  if (headerMatrices) {
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    spec.attribute("worldToCamera", OIIO::TypeMatrix44, identity);
    spec.attribute("worldToNDC", OIIO::TypeMatrix44, identity);
  }
  const std::string path = folder + "/c.0003.exr";
  writeImage(path, spec, std::vector<float>(2 * 2 * 4, 0.5f));
  return path;
}

AovLayout colorOnly(const std::string& folder) {
  AovLayout layout;
  layout.color = {folder + "/c.####.exr", {"R", "G", "B", "A"}};
  return layout;
}

TEST(ReadFrameCameraNote, TheNoteGivesCameraAndJitterOverTheHeaderMatrices) {
  const std::string folder = scratchFolder();
  writeFrame(folder, kNote, true);
  const FrameData data = readFrame(colorOnly(folder), 3);
  EXPECT_EQ(data.cameraOrigin, CameraOrigin::Note);
  EXPECT_EQ(data.ndc, CameraSidecar::kNdc);
  EXPECT_EQ(data.noteJitter, glm::vec2(0.16666669f, -0.2777778f));
  EXPECT_DOUBLE_EQ((data.camera->worldToCamera * glm::dvec4(0, 0, 0, 1)).z, 5.0);

  writeFrame(folder, "", true);
  const FrameData plain = readFrame(colorOnly(folder), 3);
  EXPECT_EQ(plain.cameraOrigin, CameraOrigin::HeaderMatrices);
  EXPECT_FALSE(plain.noteJitter.has_value());
  writeFrame(folder, "");
  EXPECT_EQ(readFrame(colorOnly(folder), 3).cameraOrigin, CameraOrigin::None);
}

TEST(ReadFrameCameraNote, TheSidecarsCameraWinsAndTheNotesJitterIsStillRead) {
  const std::string folder = scratchFolder();
  writeFrame(folder, kNote);
  writeTextFile(folder + "/camera.json",
                R"({"frames": {"3": {"view": [1,0,0,0,0,1,0,0,0,0,1,0,0,0,-9,1],)"
                R"("projection": [1,0,0,0,0,1,0,0,0,0,1,-1,0,0,0,0]}}})");
  const CameraSidecar sidecar = CameraSidecar::load(folder + "/camera.json");
  const FrameData data = readFrame(colorOnly(folder), 3, {NdcConvention::ZeroOneYDown, &sidecar});
  EXPECT_EQ(data.cameraOrigin, CameraOrigin::Sidecar);
  EXPECT_DOUBLE_EQ((data.camera->worldToCamera * glm::dvec4(0, 0, 0, 1)).z, 9.0);
  EXPECT_EQ(data.noteJitter, glm::vec2(0.16666669f, -0.2777778f));
}

TEST(ReadFrameCameraNote, ABadNoteFailsTheReadUnlessTheNoteIsNotRead) {
  const std::string folder = scratchFolder();
  const std::string path = writeFrame(folder, R"(taa-camera/1 {"view":[1,2]})", true);
  const Error error = errorOf([&] { readFrame(colorOnly(folder), 3); });
  EXPECT_EQ(error.context().file, path);
  EXPECT_EQ(error.context().frame, 3);
  EXPECT_EQ(error.context().channel, "Note");
  EXPECT_TRUE(contains(error.what(), "(frame 3, channel Note)")) << error.what();
  CameraInputs withoutNote;
  withoutNote.readNote = false;
  const FrameData data = readFrame(colorOnly(folder), 3, withoutNote);
  EXPECT_EQ(data.cameraOrigin, CameraOrigin::HeaderMatrices);
  EXPECT_FALSE(data.noteJitter.has_value());
}

}  // namespace
}  // namespace taa::io
