// The Blender add-on (plugin/blender) used as a user does: the zip installed and enabled in a
// throwaway Blender user folder, the scene rendered headless through it with the README's
// command, the frames resolved by taatool with no flag but --preset cycles. The scene
// (addon_scene.py) is the conventions scene, its surfaces emitting their world position, with
// every setting taa needs set otherwise; Blender's own reference cameras come from the scene,
// without the add-on.
#include <unistd.h>

#include <OpenImageIO/imageio.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "../e2e/taatool_runner.h"
#include "io/aov_layout.h"
#include "io/camera_sidecar.h"
#include "io/frame_reader.h"
#include "resolve/camera.h"
#include "resolve/jitter.h"
#include "blender_tmpdir.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::runProgram;
using test::runTaatool;
using test::ToolRun;

constexpr int kFirst = 1, kLast = 5, kWidth = 64, kHeight = 36;

std::string readText(const fs::path& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Runs Blender with the test's user folders; a failure names the step and its log.
ToolRun blender(const fs::path& folder, const std::string& step,
                const std::vector<std::string>& args) {
  const fs::path scratch = folder / step;
  fs::create_directories(scratch);
  test::keepBlendersTemporaryFilesInTheTestFolder();
  ToolRun run = runProgram("blender", args, scratch);
  run.out += run.err;  // Blender prints its messages and Python's on both
  return run;
}

// Install, enable and render once per test process (CTest runs each test in its own).
struct Rendered {
  fs::path folder;
  ToolRun render;
  std::string pattern() const { return (folder / "frames" / "input_####.exr").string(); }
};

const Rendered& rendered() {
  static const Rendered result = [] {
    Rendered r;
    r.folder = fs::path(TAA_TEST_TMPDIR) / ("blender_addon_" + std::to_string(getpid()));
    fs::remove_all(r.folder);
    fs::create_directories(r.folder);
    // Blender reads these at start: the add-on goes into a user folder of the test's own.
    setenv("BLENDER_USER_CONFIG", (r.folder / "config").c_str(), 1);
    setenv("BLENDER_USER_SCRIPTS", (r.folder / "scripts").c_str(), 1);
    const ToolRun build = blender(r.folder, "build",
        {"-b", "--factory-startup", "-noaudio", "-P", TAA_ADDON_SCENE_SCRIPT, "--", "--build",
         r.folder.string()});
    EXPECT_EQ(build.exitCode, 0) << build.out;
    // README "Rendering input for taa", step 1.
    const ToolRun install = blender(r.folder, "install",
        {"-b", "-noaudio", "--python-exit-code", "1", "--python-expr",
         "import bpy; bpy.ops.preferences.addon_install(filepath='" +
             std::string(TAA_BLENDER_ADDON_ZIP) +
             "'); bpy.ops.preferences.addon_enable(module='taa_render'); "
             "bpy.ops.wm.save_userpref()"});
    EXPECT_EQ(install.exitCode, 0) << install.out;
    // Step 2, with the sidecar asked for; then the scene's settings as the render left them.
    r.render = blender(r.folder, "render",
        {"-b", (r.folder / "scene.blend").string(), "-noaudio", "--python-exit-code", "1",
         "--python-expr",
         "import bpy; bpy.context.scene.taa_render.write_sidecar = True; bpy.ops.taa.render()",
         "-P", TAA_ADDON_SCENE_SCRIPT, "--", "--snapshot", (r.folder / "after.json").string()});
    EXPECT_EQ(r.render.exitCode, 0) << r.render.out;
    return r;
  }();
  return result;
}

io::FrameData readRendered(int frame) {
  return io::readFrame(io::cyclesLayout(rendered().pattern()), frame);
}

void expectNearMatrix(const glm::dmat4& actual, const glm::dmat4& expected, double tolerance,
                      const std::string& what) {
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      EXPECT_NEAR(actual[c][r], expected[c][r], tolerance * std::max(1.0, std::abs(expected[c][r])))
          << what << ", column " << c << ", row " << r;
    }
  }
}

TEST(BlenderAddon, EachFramesHeaderHoldsTheScenesCameraAndTheHaltonJitter) {
  const io::CameraSidecar reference =
      io::CameraSidecar::load((rendered().folder / "reference.json").string());
  for (int f = kFirst; f <= kLast; ++f) {
    const io::FrameData frame = readRendered(f);
    ASSERT_EQ(frame.cameraOrigin, io::CameraOrigin::Note) << "frame " << f;
    ASSERT_TRUE(frame.noteJitter.has_value()) << "frame " << f;
    // The note states taatool's default jitter, to the bit.
    EXPECT_EQ(*frame.noteJitter, frameJitter(f, JitterOptions{})) << "frame " << f;
    EXPECT_EQ(*frame.noteJitter, reference.jitter(f)) << "frame " << f;
    // The scene's camera, unjittered, with the user's own lens shift.
    const std::string name = "frame " + std::to_string(f);
    expectNearMatrix(frame.camera->worldToCamera, reference.camera(f).worldToCamera, 1e-6,
                     name + " worldToCamera");
    expectNearMatrix(frame.camera->worldToNdc, reference.camera(f).worldToNdc, 1e-6,
                     name + " worldToNdc");
  }
}

// Raster position (pixels, y down) of a world point in a frame's camera.
glm::dvec2 rasterOf(const io::FrameData& frame, const glm::dvec3& world) {
  const glm::dmat4 toRaster = glm::inverse(ndcFromRaster({0, 0, kWidth, kHeight}, frame.ndc));
  const glm::dvec4 clip = frame.camera->worldToNdc * glm::dvec4(world, 1.0);
  const glm::dvec4 raster = toRaster * (clip / clip.w);
  return {raster.x, raster.y};
}

// Each 1-spp sample emits its world position: projected with the note's camera it must land
// at the pixel centre plus the note's jitter. This holds only if the add-on shifted the lens by
// that jitter and took it out of the projection it wrote.
TEST(BlenderAddon, EachSampleLandsWhereTheNoteSays) {
  for (int f = kFirst; f <= kLast; ++f) {
    const io::FrameData frame = readRendered(f);
    ASSERT_TRUE(frame.camera && frame.noteJitter);
    const Image* color = frame.color.floats();
    ASSERT_NE(color, nullptr) << "the scene renders float colour";
    int hits = 0;
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        if (std::isinf(frame.depth.at(x, y)[0])) continue;
        const float* p = color->at(x, y);
        const glm::dvec2 sample = rasterOf(frame, {p[0], p[1], p[2]});
        const glm::dvec2 expected(x + 0.5 + frame.noteJitter->x, y + 0.5 + frame.noteJitter->y);
        worst = std::max(worst, glm::length(sample - expected));
        ++hits;
      }
    }
    EXPECT_GT(hits, kWidth * kHeight / 2) << "frame " << f;
    EXPECT_LT(worst, 0.01) << "frame " << f << ": a sample is " << worst << " px off the note";
  }
}

TEST(BlenderAddon, TheSidecarHoldsTheNotesNumbers) {
  const io::CameraSidecar sidecar =
      io::CameraSidecar::load((rendered().folder / "frames" / "taa_camera.json").string());
  for (int f = kFirst; f <= kLast; ++f) {
    const io::FrameData frame = readRendered(f);
    EXPECT_EQ(sidecar.jitter(f), *frame.noteJitter) << "frame " << f;
    EXPECT_EQ(sidecar.camera(f).worldToCamera, frame.camera->worldToCamera) << "frame " << f;
    EXPECT_EQ(sidecar.camera(f).worldToNdc, frame.camera->worldToNdc) << "frame " << f;
  }
}

TEST(BlenderAddon, WhatTheResolveNeedsIsSetWithAMessageAndPutBackAfterTheRender) {
  const std::string& log = rendered().render.out;
  for (const std::string message :
       {"Motion blur: on -> off (Cycles writes no Vector pass with it on)",
        "Pixel filter: 'GAUSSIAN' -> 'BOX'", "Pixel filter width: 1.5 -> 1.0",
        "Denoising: on -> off", "File format: 'OPEN_EXR' -> 'OPEN_EXR_MULTILAYER'",
        "Stamp burn-in: on -> off", "Stamp note: off -> on", "Depth pass (ViewLayer): off -> on",
        "Vector pass (ViewLayer): off -> on", "settings and lens shift put back"}) {
    EXPECT_NE(log.find(message), std::string::npos) << message << " in\n" << log;
  }
  // Every setting, the user's note and lens shift included, as the scene had them.
  const std::string before = readText(rendered().folder / "before.json");
  EXPECT_FALSE(before.empty());
  EXPECT_EQ(readText(rendered().folder / "after.json"), before);
  // Motion blur was really off: Cycles writes zero vectors with it on.
  const io::FrameData frame = readRendered(3);
  float largest = 0.0f;
  for (float v : frame.motion.pixels) largest = std::max(largest, std::abs(v));
  EXPECT_GT(largest, 1.0f) << "the camera moves by pixels a frame";
}

// Issue 22's "multilayer EXR, half colour, float depth and vectors", from a scene that wrote
// 8-bit PNGs, through a still render (F12 in the UI).
TEST(BlenderAddon, AStillOfAPngSceneGetsHalfColourFloatDataItsNoteAndThePngBack) {
  const fs::path folder = rendered().folder;
  const ToolRun still = blender(folder, "still_log",
      {"-b", (folder / "scene.blend").string(), "-noaudio", "--python-exit-code", "1", "-P",
       TAA_ADDON_SCENE_SCRIPT, "--", "--png-still", folder.string()});
  ASSERT_EQ(still.exitCode, 0) << still.out;
  EXPECT_NE(still.out.find("Colour depth: '8' -> '16'"), std::string::npos) << still.out;
  EXPECT_EQ(still.out.find("could not put back"), std::string::npos) << still.out;
  const std::string path = (folder / "still" / "frame.exr").string();
  auto input = OIIO::ImageInput::open(path);
  ASSERT_TRUE(input) << path;
  const OIIO::ImageSpec& spec = input->spec();
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& name = spec.channelnames[std::size_t(c)];
    const bool colour = name.find(".Combined.") != std::string::npos;
    EXPECT_EQ(spec.channelformat(c), colour ? OIIO::TypeHalf : OIIO::TypeFloat) << name;
  }
  const io::FrameData frame = io::readFrame(io::cyclesLayout(path), 3);
  EXPECT_EQ(frame.cameraOrigin, io::CameraOrigin::Note);
  EXPECT_EQ(frame.noteJitter, frameJitter(3, JitterOptions{}));
  EXPECT_EQ(readText(folder / "still" / "after.json"), readText(folder / "still" / "before.json"));
}

std::vector<float> readPixels(const std::string& path) {
  auto input = OIIO::ImageInput::open(path);
  EXPECT_TRUE(input) << path;
  if (!input) return {};
  const OIIO::ImageSpec& spec = input->spec();
  std::vector<float> pixels(spec.image_pixels() * spec.nchannels);
  EXPECT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, pixels.data())) << path;
  return pixels;
}

TEST(BlenderAddon, TaatoolWithNoFlagsEqualsTheSidecarRunBitForBit) {
  const fs::path folder = rendered().folder / "resolve";
  fs::create_directories(folder / "header");
  fs::create_directories(folder / "sidecar");
  const ToolRun header = runTaatool(
      {"--preset", "cycles", rendered().pattern(), "-o",
       (folder / "header" / "o.####.exr").string(), "-v"},
      folder / "header");
  ASSERT_EQ(header.exitCode, 0) << header.err;
  const std::string said = header.out + header.err;
  EXPECT_NE(said.find("frame 1: camera from the color header's camera note (Note), jitter from "
                      "the color header's camera note"),
            std::string::npos)
      << said;
  const ToolRun sidecar = runTaatool(
      {"--preset", "cycles", rendered().pattern(), "--camera-sidecar",
       (rendered().folder / "frames" / "taa_camera.json").string(), "--jitter", "sidecar", "-o",
       (folder / "sidecar" / "o.####.exr").string(), "-v"},
      folder / "sidecar");
  ASSERT_EQ(sidecar.exitCode, 0) << sidecar.err;
  EXPECT_NE((sidecar.out + sidecar.err).find("camera from the camera sidecar, jitter from the "
                                             "camera sidecar"),
            std::string::npos);
  for (int f = kFirst; f <= kLast; ++f) {
    char name[16];
    std::snprintf(name, sizeof name, "o.%04d.exr", f);
    const std::vector<float> a = readPixels((folder / "header" / name).string());
    const std::vector<float> b = readPixels((folder / "sidecar" / name).string());
    // The colour, then the render's depth and vectors (every pass is written beside it).
    ASSERT_EQ(a.size(), std::size_t(kWidth) * kHeight * 9) << name;
    EXPECT_TRUE(a == b) << name << ": the header run differs from the sidecar run";
  }
}

// The README's first hour (issue 24): install, render through the add-on, resolve with the
// README's command and look, with $OCIO set to Blender's own config as an artist's shell has
// it. The resolve runs (the bracket is taa's own) and gives the pixels of the run without
// $OCIO, bit for bit; the header says the colour is Blender's scene-linear "Linear".
TEST(BlenderAddon, TheReadmesFirstHourWorksWithBlendersOcio) {
  constexpr const char* kBlenderConfig =
      "/usr/share/blender/datafiles/colormanagement/config.ocio";
  const fs::path folder = rendered().folder / "first_hour";
  fs::create_directories(folder);
  const ToolRun plain = runTaatool(
      {"--preset", "cycles", rendered().pattern(), "-o", (folder / "plain" / "o.####.exr").string()},
      folder);
  ASSERT_EQ(plain.exitCode, 0) << plain.err;
  setenv("OCIO", kBlenderConfig, 1);
  const ToolRun studio = runTaatool(
      {"--preset", "cycles", rendered().pattern(), "-o", (folder / "ocio" / "o.####.exr").string()},
      folder);
  const ToolRun look = test::runProgram(
      "oiiotool", {(folder / "ocio" / "o.0002.exr").string(), "--ch",
                   "ViewLayer.Combined.R,ViewLayer.Combined.G,ViewLayer.Combined.B",
                   "--colorconvert", "Linear", "sRGB", "-o", (folder / "look.png").string()},
      folder);
  unsetenv("OCIO");
  ASSERT_EQ(studio.exitCode, 0) << studio.err;
  for (int f = kFirst; f <= kLast; ++f) {
    char name[16];
    std::snprintf(name, sizeof name, "o.%04d.exr", f);
    EXPECT_TRUE(readPixels((folder / "plain" / name).string()) ==
                readPixels((folder / "ocio" / name).string()))
        << name;
  }
  auto in = OIIO::ImageInput::open((folder / "ocio" / "o.0002.exr").string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().get_string_attribute("taa:colorspace"), "Linear");
  EXPECT_EQ(look.exitCode, 0) << look.err;
  EXPECT_TRUE(fs::exists(folder / "look.png"));
}

TEST(BlenderAddon, AScenePastFixingIsRefusedWithAMessage) {
  const fs::path folder = rendered().folder;
  const ToolRun refused = blender(folder, "refused",
      {"-b", (folder / "scene.blend").string(), "-noaudio", "--python-exit-code", "1",
       "--python-expr",
       "import bpy; s = bpy.context.scene; s.render.engine = 'BLENDER_WORKBENCH'; "
       "s.render.filepath = '" + (folder / "refused" / "frame_").string() + "'; "
       "bpy.ops.taa.render()"});
  EXPECT_NE(refused.exitCode, 0) << refused.out;
  EXPECT_NE(refused.out.find("taa cannot render this scene: the render engine is "
                             "BLENDER_WORKBENCH"),
            std::string::npos)
      << refused.out;
  EXPECT_FALSE(fs::exists(folder / "refused" / "frame_0001.png"));
  EXPECT_FALSE(fs::exists(folder / "refused" / "frame_0001.exr"));
}

}  // namespace
}  // namespace taa
