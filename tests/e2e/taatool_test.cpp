// End-to-end: run the taatool binary on generated sequences, check outputs, errors and exit codes.
#include <gtest/gtest.h>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"
#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

using test::ToolRun;

class TaatoolTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder(); }

  ToolRun run(const std::vector<std::string>& args) const { return test::runTaatool(args, dir_); }

  // Writes frames [first, last] of a small scene into dir_/name in the given layout.
  fs::path generate(const std::string& name, scenes::OutputLayout layout, int first = 1,
                    int last = 6, const std::string& scene = "moving_object") const {
    const fs::path folder = dir_ / name;
    auto s = scenes::makeScene(scene, 64, 40);
    scenes::RenderSettings settings;
    settings.truthSamplesPerAxis = 4;  // truth is not what these tests check
    for (int f = first; f <= last; ++f) {
      scenes::writeFrame(s->render(f, settings), scene, layout, folder.string());
    }
    return folder;
  }

  std::vector<std::string> separateArgs(const fs::path& in, const fs::path& outPattern) const {
    return {(in / "beauty.####.exr").string(), "--depth", (in / "depth.####.exr").string(),
            "--motion", (in / "motion.####.exr").string(), "-o", outPattern.string()};
  }

  // Everything in `folder` whose name contains `part` (outputs, temp files).
  static std::vector<std::string> filesContaining(const fs::path& folder, const std::string& part) {
    std::vector<std::string> names;
    if (!fs::exists(folder)) return names;
    for (const auto& e : fs::directory_iterator(folder)) {
      const std::string name = e.path().filename().string();
      if (name.find(part) != std::string::npos) names.push_back(name);
    }
    return names;
  }

  void expectError(const ToolRun& r, const std::vector<std::string>& fragments) const {
    test::expectToolError(r, fragments);
  }

  fs::path dir_;
};

std::vector<float> readPixels(const fs::path& path, OIIO::ImageSpec* specOut = nullptr) {
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path;
  if (!in) return {};
  const OIIO::ImageSpec spec = in->spec();
  if (specOut) *specOut = spec;
  std::vector<float> pixels(spec.image_pixels() * spec.nchannels);
  in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data());
  return pixels;
}

TEST_F(TaatoolTest, ResolvesSeparateFilesIntoRgbaExrKeepingWindows) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate);
  const fs::path out = dir_ / "out";
  auto args = separateArgs(in, out / "resolved.####.exr");
  args.push_back("-v");
  const ToolRun r = run(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("frame 6 (6/6, "), std::string::npos) << r.out;
  for (int f = 1; f <= 6; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "resolved.%04d.exr", f);
    ASSERT_TRUE(fs::exists(out / name)) << name;
  }
  OIIO::ImageSpec spec, inSpec;
  readPixels(out / "resolved.0003.exr", &spec);
  readPixels(in / "beauty.0003.exr", &inSpec);
  EXPECT_EQ(spec.nchannels, 4);
  EXPECT_EQ(spec.channelnames, (std::vector<std::string>{"R", "G", "B", "A"}));
  EXPECT_EQ(spec.format, inSpec.format);  // the input's pixel type unless -d says otherwise
  EXPECT_EQ(spec.width, inSpec.width);
  EXPECT_EQ(spec.full_width, inSpec.full_width);
  EXPECT_EQ(spec.x, inSpec.x);
  EXPECT_EQ(spec.get_string_attribute("compression"), "zip");
  EXPECT_TRUE(filesContaining(out, "tmp").empty());
}

TEST_F(TaatoolTest, CyclesLayoutGivesTheSameOutputAsSeparateFiles) {
  const fs::path separate = generate("separate", scenes::OutputLayout::Separate);
  const fs::path cycles = generate("cycles", scenes::OutputLayout::Cycles);
  auto args = separateArgs(separate, dir_ / "a.####.exr");
  args.insert(args.end(), {"-d", "float"});
  ASSERT_EQ(run(args).exitCode, 0);
  // The colour compared: the file's depth and vectors, written beside it, dropped.
  const ToolRun r = run({"--preset", "cycles", (cycles / "render.####.exr").string(), "-d",
                           "float", "--aov", "*=drop", "-o", (dir_ / "b.####.exr").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (int f : {1, 4, 6}) {
    char a[32], b[32];
    std::snprintf(a, sizeof a, "a.%04d.exr", f);
    std::snprintf(b, sizeof b, "b.%04d.exr", f);
    const auto pa = readPixels(dir_ / a), pb = readPixels(dir_ / b);
    ASSERT_EQ(pa.size(), pb.size());
    for (std::size_t i = 0; i < pa.size(); ++i) ASSERT_NEAR(pa[i], pb[i], 1e-5f) << f << ":" << i;
  }
}

TEST_F(TaatoolTest, MissingFrameInRange) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate);
  fs::remove(in / "motion.0004.exr");
  auto args = separateArgs(in, dir_ / "out" / "r.####.exr");
  args.insert(args.end(), {"--frames", "1-6"});
  expectError(run(args), {"missing input frame", "motion.0004.exr", "frame 4", "motion"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));  // checked before any frame is written
}

TEST_F(TaatoolTest, MissingChannelListsAvailableOnes) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 2);
  auto args = separateArgs(in, dir_ / "r.####.exr");
  args.insert(args.end(), {"--depth-ch", "depth.Z"});
  expectError(run(args), {"depth.Z", "depth.0001.exr", "frame 1", "Z"});
  EXPECT_TRUE(filesContaining(dir_, "r.0").empty());
}

TEST_F(TaatoolTest, DepthOrMotionSizeDifferentFromColor) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 3);
  const fs::path small = generate("small", scenes::OutputLayout::Separate, 3, 3);
  {
    auto s = scenes::makeScene("moving_object", 32, 20);
    scenes::RenderSettings settings;
    settings.truthSamplesPerAxis = 1;
    scenes::writeFrame(s->render(3, settings), "moving_object", scenes::OutputLayout::Separate,
                       small.string());
  }
  fs::copy_file(small / "motion.0003.exr", in / "motion.0003.exr",
                fs::copy_options::overwrite_existing);
  auto history = separateArgs(in, dir_ / "out" / "r.####.exr");
  history.insert(history.end(), {"--mode", "history"});
  expectError(run(history), {"motion.0003.exr", "frame 3", "32x20", "64x40"});
  EXPECT_FALSE(fs::exists(dir_ / "out" / "r.0003.exr"));
  EXPECT_TRUE(fs::exists(dir_ / "out" / "r.0002.exr"));  // earlier frames are complete files
  EXPECT_TRUE(filesContaining(dir_ / "out", "tmp").empty());
  // The window resolve (the default): every frame's window holds frame 3, so none is written.
  expectError(run(separateArgs(in, dir_ / "window" / "r.####.exr")),
              {"motion.0003.exr", "frame 3", "32x20", "64x40"});
  EXPECT_TRUE(filesContaining(dir_ / "window", "r.").empty());
}

TEST_F(TaatoolTest, NonExrAndTruncatedFiles) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 3);
  std::ofstream(in / "beauty.0002.exr") << "this is not an EXR file\n";
  expectError(run(separateArgs(in, dir_ / "o1" / "r.####.exr")), {"beauty.0002.exr", "frame 2"});
  EXPECT_FALSE(fs::exists(dir_ / "o1" / "r.0002.exr"));

  const fs::path in2 = generate("in2", scenes::OutputLayout::Separate, 1, 3);
  const fs::path victim = in2 / "depth.0003.exr";
  fs::resize_file(victim, fs::file_size(victim) / 2);
  expectError(run(separateArgs(in2, dir_ / "o2" / "r.####.exr")),
              {"depth.0003.exr", "frame 3"});
  EXPECT_FALSE(fs::exists(dir_ / "o2" / "r.0003.exr"));
  EXPECT_TRUE(filesContaining(dir_ / "o2", "tmp").empty());
}

TEST_F(TaatoolTest, OutputPatternEqualToAnInput) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 2);
  const auto before = fs::file_size(in / "beauty.0001.exr");
  // Same files spelled differently: another placeholder style and a "./" detour.
  const ToolRun r = run(separateArgs(in, in / "." / "beauty.%04d.exr"));
  expectError(r, {"output would overwrite an input file", "beauty.0001.exr"});
  EXPECT_EQ(fs::file_size(in / "beauty.0001.exr"), before);
}

// TAA_GL_IMAGE_STORES=0 turns the image stores off (the passes' draw buffers instead).
TEST_F(TaatoolTest, InfoSaysWhenImageStoresAreTurnedOff) {
  setenv("TAA_GL_IMAGE_STORES", "0", 1);
  const ToolRun r = run({"--info"});
  unsetenv("TAA_GL_IMAGE_STORES");
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("Image stores:    none (the passes' gather in draws of six groups)"),
            std::string::npos)
      << r.out;
}

TEST_F(TaatoolTest, UnknownGlBackend) {
  expectError(run({"--info", "--gl", "vulkan"}), {"vulkan", "auto", "egl", "osmesa"});
}

TEST_F(TaatoolTest, InfoReportsAWorkingContextForEachBackend) {
  for (const char* backend : {"egl", "osmesa"}) {
    const ToolRun r = run({"--info", "--gl", backend});
    EXPECT_EQ(r.exitCode, 0) << backend << ": " << r.err;
    EXPECT_NE(r.out.find(std::string("GL back end:     ") + backend), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("GL self-test:    passed"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("GL renderer:     "), std::string::npos) << r.out;
    // llvmpipe has OpenGL 4.5, image stores included, on either back end.
    EXPECT_NE(r.out.find("images a shader (the passes' gather in one draw)"), std::string::npos)
        << r.out;
    EXPECT_NE(r.out.find("OpenColorIO:     2."), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("OpenImageIO:     2."), std::string::npos) << r.out;
    // OpenEXR's ZIP codec runs on libdeflate in taatool (fast_zlib).
    EXPECT_NE(r.out.find("EXR zlib codec:  libdeflate"), std::string::npos) << r.out;
  }
}

TEST_F(TaatoolTest, BracketsListedAndChosen) {
  const ToolRun list = run({"--list-brackets"});
  EXPECT_EQ(list.exitCode, 0) << list.err;
  EXPECT_NE(list.out.find("OCIO config: taa's shipped config"), std::string::npos) << list.out;
  EXPECT_NE(list.out.find("  taa_reinhard\n"), std::string::npos) << list.out;

  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 2);
  auto args = separateArgs(in, dir_ / "o" / "r.####.exr");
  args.insert(args.end(), {"--bracket", "taa_reinhard"});
  const ToolRun ok = run(args);
  EXPECT_EQ(ok.exitCode, 0) << ok.err;
  EXPECT_TRUE(fs::exists(dir_ / "o" / "r.0002.exr"));

  auto bad = separateArgs(in, dir_ / "bad" / "r.####.exr");
  bad.insert(bad.end(), {"--bracket", "filmic_nope"});
  expectError(run(bad), {"filmic_nope", "shipped config"});
  EXPECT_FALSE(fs::exists(dir_ / "bad"));

  expectError(run({"--list-brackets", "--ocio-config", (dir_ / "missing.ocio").string()}),
              {"cannot load the OCIO config", "missing.ocio"});
}

TEST_F(TaatoolTest, PipelinedAndSerialRunsAreBitIdentical) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 8);
  // Half: the native path (half read, uploaded and read back as half); float: widened output.
  for (const std::string type : {"half", "float"}) {
    SCOPED_TRACE(type);
    for (const std::string threads : {"0", "3"}) {
      auto args = separateArgs(in, dir_ / (type + "-t" + threads) / "r.####.exr");
      args.insert(args.end(), {"--threads", threads, "-d", type});
      const ToolRun r = run(args);
      ASSERT_EQ(r.exitCode, 0) << r.err;
    }
    for (int f = 1; f <= 8; ++f) {
      char name[32];
      std::snprintf(name, sizeof name, "r.%04d.exr", f);
      OIIO::ImageSpec spec;
      const auto serial = readPixels(dir_ / (type + "-t0") / name, &spec);
      const auto pipelined = readPixels(dir_ / (type + "-t3") / name);
      ASSERT_FALSE(serial.empty());
      EXPECT_EQ(spec.format, type == "half" ? OIIO::TypeHalf : OIIO::TypeFloat);
      EXPECT_EQ(serial, pipelined) << name;
    }
  }
  expectError(run({"--threads", "-1"}), {"--threads"});
}

// The window mode's promise to a farm: any split of the shot writes the whole run's pixels.
TEST_F(TaatoolTest, WindowSubRangesWriteTheWholeRunsPixels) {
  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 10);
  auto whole = separateArgs(in, dir_ / "whole" / "r.####.exr");
  whole.insert(whole.end(), {"--mode", "window", "--window", "2", "--frames", "1-10"});
  ASSERT_EQ(run(whole).exitCode, 0);
  for (const std::string range : {"1-3", "4-7", "8-10", "5"}) {
    auto part = separateArgs(in, dir_ / "parts" / "r.####.exr");
    part.insert(part.end(), {"--mode", "window", "--window", "2", "--frames", range});
    const ToolRun r = run(part);
    ASSERT_EQ(r.exitCode, 0) << range << ": " << r.err;
  }
  for (int f = 1; f <= 10; ++f) {
    char name[32];
    std::snprintf(name, sizeof name, "r.%04d.exr", f);
    const auto expected = readPixels(dir_ / "whole" / name);
    ASSERT_FALSE(expected.empty());
    EXPECT_EQ(readPixels(dir_ / "parts" / name), expected) << name;
  }
}

// Without camera matrices the window carries every sample along its vectors, and -v says so.
TEST_F(TaatoolTest, WindowWithoutCamerasFollowsVectorsAndSaysSo) {
  // A 3D scene: its headers carry the camera matrices.
  const fs::path in = generate("in", scenes::OutputLayout::Separate, 1, 5, "rotate_yaw");
  auto args = separateArgs(in, dir_ / "with" / "r.####.exr");
  args.insert(args.end(), {"--mode", "window", "--window", "2", "-v"});
  const ToolRun withCameras = run(args);
  ASSERT_EQ(withCameras.exitCode, 0) << withCameras.err;
  EXPECT_EQ(withCameras.err.find("no camera matrices"), std::string::npos) << withCameras.err;

  for (int f = 1; f <= 5; ++f) {  // the same frames, their headers without the matrices
    char name[32];
    std::snprintf(name, sizeof name, "beauty.%04d.exr", f);
    OIIO::ImageBuf frame((in / name).string());
    ASSERT_TRUE(frame.read(0, 0, true)) << frame.geterror();
    frame.specmod().erase_attribute("worldToCamera");
    frame.specmod().erase_attribute("worldToNDC");
    ASSERT_TRUE(frame.write((in / name).string())) << frame.geterror();
  }
  args = separateArgs(in, dir_ / "without" / "r.####.exr");
  args.insert(args.end(), {"--mode", "window", "--window", "2", "-v"});
  const ToolRun without = run(args);
  ASSERT_EQ(without.exitCode, 0) << without.err;
  EXPECT_NE(without.err.find("frame 1 has no camera matrices (header or sidecar): its samples "
                             "follow their motion vectors only"),
            std::string::npos)
      << without.err;
  const auto output = readPixels(dir_ / "without" / "r.0003.exr");
  ASSERT_FALSE(output.empty());
  for (float v : output) ASSERT_TRUE(std::isfinite(v));
}

TEST_F(TaatoolTest, HelpAndBadArguments) {
  const ToolRun help = run({"--help"});
  EXPECT_EQ(help.exitCode, 0);
  EXPECT_NE(help.out.find("Usage:"), std::string::npos);
  expectError(run({"--frobnicate"}), {"unknown option --frobnicate"});
  expectError(run({(dir_ / "none.####.exr").string(), "-o", (dir_ / "o.####.exr").string()}),
              {"no frames found", "none.####.exr"});
}

}  // namespace
}  // namespace taa
