// End-to-end: taatool on one scene written in several renderers' conventions and layouts must
// give the same output; overscan input keeps its windows and resolves its border; the output
// keeps the input's names, type and metadata; bad input fails clearly.
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <filesystem>
#include <fstream>

#include "resolve/option_registry.h"

#include "scenegen/convention_writers.h"
#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"
#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

using test::Exr;
using test::frameName;
using test::readExr;
using test::ToolRun;

void writeExr(const fs::path& path, const Exr& exr) {
  auto out = OIIO::ImageOutput::create("openexr");
  ASSERT_TRUE(out->open(path.string(), exr.spec)) << out->geterror();
  ASSERT_TRUE(out->write_image(OIIO::TypeFloat, exr.pixels.data())) << out->geterror();
  ASSERT_TRUE(out->close());
}

class ConventionsTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = test::freshTestFolder(); }

  ToolRun run(const std::vector<std::string>& args) const { return test::runTaatool(args, dir_); }

  // Conventions are compared without the tonemap bracket: its inverse near white would magnify
  // the rounding differences between equivalent matrix paths past the tolerances here.
  void runOk(std::vector<std::string> args) const {
    args.insert(args.end(), {"-d", "float", "-q", "--bracket", "none"});
    const ToolRun r = run(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }

  void expectError(const ToolRun& r, const std::vector<std::string>& fragments) const {
    test::expectToolError(r, fragments);
  }

  // Frames [1, last] of `scene` rendered once and written by `write` into dir_/name.
  template <typename Write>
  fs::path generate(const std::string& name, Write write, const std::string& scene, int width,
                    int height, int last) const {
    const fs::path folder = dir_ / name;
    auto s = scenes::makeScene(scene, width, height);
    scenes::RenderSettings settings;
    settings.truthSamplesPerAxis = 1;  // truth is not what these tests check
    for (int f = 1; f <= last; ++f) write(s->render(f, settings), scene, folder.string());
    return folder;
  }

  // Outputs `a` and `b` (frames 1..last) are equal within `tolerance`. From frame
  // `strictUntil + 1` on, up to `outliers` (a fraction) of the values may differ more: when the
  // same camera reaches the resolve through differently rounded matrices, a history sample lying
  // exactly on the image edge or a depth-test threshold can fall either way, and that difference
  // then lives on in history. The first reprojection (frame 2) shows any real convention error.
  void expectSameOutput(const std::string& a, const std::string& b, int last, float tolerance,
                        int strictUntil = 1 << 30, double outliers = 0.0) const {
    for (int f = 1; f <= last; ++f) {
      const Exr ea = readExr(dir_ / frameName(a, f)), eb = readExr(dir_ / frameName(b, f));
      ASSERT_EQ(ea.pixels.size(), eb.pixels.size()) << a << " vs " << b;
      float worst = 0.0f;
      std::size_t over = 0;
      for (std::size_t i = 0; i < ea.pixels.size(); ++i) {
        const float difference = std::abs(ea.pixels[i] - eb.pixels[i]);
        worst = std::max(worst, difference);
        over += difference > tolerance ? 1 : 0;
      }
      if (f <= strictUntil) {
        EXPECT_LE(worst, tolerance) << a << " vs " << b << " frame " << f;
      } else {
        EXPECT_LE(double(over), outliers * double(ea.pixels.size()))
            << a << " vs " << b << " frame " << f << " (worst " << worst << ")";
      }
    }
  }

  std::vector<std::string> separateArgs(const fs::path& in, const std::string& out) const {
    return {(in / "beauty.####.exr").string(), "--depth", (in / "depth.####.exr").string(),
            "--motion", (in / "motion.####.exr").string(),
            "-o", (dir_ / (out + ".####.exr")).string()};
  }

  fs::path dir_;
};

auto layoutWriter(scenes::OutputLayout layout) {
  return [layout](const scenes::SceneFrame& f, const std::string& scene, const std::string& dir) {
    scenes::writeFrame(f, scene, layout, dir);
  };
}

auto conventionWriter(scenes::ConventionVariant variant) {
  return [variant](const scenes::SceneFrame& f, const std::string& scene, const std::string& dir) {
    scenes::writeConventionFrame(f, scene, variant, dir);
  };
}

constexpr int kLast = 6;

TEST_F(ConventionsTest, EveryConventionVariantGivesTheSameOutput) {
  const fs::path separate = generate("separate", layoutWriter(scenes::OutputLayout::Separate),
                                     "moving_object", 64, 40, kLast);
  const fs::path cycles = generate("cycles", layoutWriter(scenes::OutputLayout::Cycles),
                                   "moving_object", 64, 40, kLast);
  const fs::path nuke = generate("nuke", conventionWriter(scenes::ConventionVariant::Nuke),
                                 "moving_object", 64, 40, kLast);
  const fs::path ndc = generate("ndc", conventionWriter(scenes::ConventionVariant::NdcSeparate),
                                "moving_object", 64, 40, kLast);
  runOk(separateArgs(separate, "internal"));
  // The colour is compared: the depth and motion channels these files hold beside it (written
  // by the window mode as every pass is) are dropped.
  runOk({"--preset", "cycles", (cycles / "render.####.exr").string(), "--aov", "*=drop", "-o",
         (dir_ / "cycles.####.exr").string()});
  runOk({"--preset", "nuke", (nuke / "nuke.####.exr").string(), "--aov", "*=drop", "-o",
         (dir_ / "nuke.####.exr").string()});
  runOk({(ndc / "color.####.exr").string(), "--depth", (ndc / "depth_ndc.####.exr").string(),
         "--motion", (ndc / "motion_ndc.####.exr").string(), "--depth-kind", "ndc",
         "--depth-near", "1", "--depth-far", "1000", "--motion-units", "ndc", "--motion-y", "up",
         "-o", (dir_ / "ndc.####.exr").string()});
  // The jitter the generator wrote into each header is the Halton default.
  auto fromHeader = separateArgs(separate, "header_jitter");
  fromHeader.insert(fromHeader.end(), {"--jitter", "header:taa:jitter"});
  runOk(fromHeader);

  for (const char* variant : {"cycles", "nuke", "ndc", "header_jitter"}) {
    expectSameOutput("internal", variant, kLast, 1e-5f);
  }
}

// Rewrites frame files of `in` into `out` as overscan: the data window keeps every pixel but
// the display window shrinks by `border` on each side; worldToNDC is re-based on the smaller
// display window, so the pixels mean exactly what they meant before.
void writeAsOverscan(const fs::path& in, const fs::path& out, const std::string& stem, int last,
                     int border) {
  fs::create_directories(out);
  for (int f = 1; f <= last; ++f) {
    Exr exr = readExr(in / frameName(stem, f));
    const int w = exr.spec.width, h = exr.spec.height;
    exr.spec.x = exr.spec.y = -border;
    exr.spec.full_x = exr.spec.full_y = 0;
    exr.spec.full_width = w - 2 * border;
    exr.spec.full_height = h - 2 * border;
    if (const auto* m = exr.spec.find_attribute("worldToNDC", OIIO::TypeMatrix44)) {
      // X' = (w / w') X - (border / w') W, and likewise for Y (column-vector matrices).
      glm::mat4 rebase(1.0f);
      rebase[0][0] = float(w) / float(exr.spec.full_width);
      rebase[3][0] = -float(border) / float(exr.spec.full_width);
      rebase[1][1] = float(h) / float(exr.spec.full_height);
      rebase[3][1] = -float(border) / float(exr.spec.full_height);
      const glm::mat4 rebased = rebase * glm::make_mat4(static_cast<const float*>(m->data()));
      exr.spec.attribute("worldToNDC", OIIO::TypeMatrix44, glm::value_ptr(rebased));
    }
    writeExr(out / frameName(stem, f), exr);
  }
}

TEST_F(ConventionsTest, OverscanKeepsItsWindowsAndResolvesTheBorder) {
  // A rotating camera, reprojected from the camera alone: a wrong raster window would move
  // every history sample.
  constexpr int kFrames = 4, kBorder = 4;
  const fs::path full = generate("full", layoutWriter(scenes::OutputLayout::Separate),
                                 "rotate_yaw", 72, 48, kFrames);
  const fs::path over = dir_ / "over";
  for (const char* stem : {"beauty", "depth", "motion"}) {
    writeAsOverscan(full, over, stem, kFrames, kBorder);
  }
  for (const std::string mode : {"history", "window"}) {
    auto fullArgs = separateArgs(full, mode + "_full_out");
    auto overArgs = separateArgs(over, mode + "_over_out");
    for (auto* args : {&fullArgs, &overArgs}) {
      args->insert(args->end(), {"--camera-motion", "camera", "--mode", mode});
      runOk(*args);
    }
    const Exr out = readExr(dir_ / frameName(mode + "_over_out", kFrames));
    EXPECT_EQ(out.spec.x, -kBorder);
    EXPECT_EQ(out.spec.y, -kBorder);
    EXPECT_EQ(out.spec.width, 72);
    EXPECT_EQ(out.spec.full_x, 0);
    EXPECT_EQ(out.spec.full_width, 72 - 2 * kBorder);
    EXPECT_EQ(out.spec.full_height, 48 - 2 * kBorder);
    // Every pixel, the border included, as resolved from the full-frame render. The window
    // resolve gathers from every frame of its window from frame 1 on (no first frame alone).
    expectSameOutput(mode + "_full_out", mode + "_over_out", kFrames, 1e-4f,
                     mode == "history" ? 2 : 0, 0.01);
  }
}

TEST_F(ConventionsTest, SidecarCameraAndJitterMatchTheHeaders) {
  constexpr int kFrames = 4;
  const fs::path in = generate("in", layoutWriter(scenes::OutputLayout::Separate), "rotate_yaw",
                               48, 32, kFrames);
  // The sidecar holds the same cameras as OpenGL view / projection matrices.
  std::ofstream json(dir_ / "camera.json");
  json << "{\"frames\": {";
  for (int f = 1; f <= kFrames; ++f) {
    const Exr exr = readExr(in / frameName("beauty", f));
    const auto* toCamera = exr.spec.find_attribute("worldToCamera", OIIO::TypeMatrix44);
    const auto* toNdc = exr.spec.find_attribute("worldToNDC", OIIO::TypeMatrix44);
    ASSERT_TRUE(toCamera && toNdc);
    glm::dmat4 flipZ(1.0), toGlNdc(1.0);
    flipZ[2][2] = -1.0;
    toGlNdc[0][0] = 2.0;  // x: 2X - W
    toGlNdc[3][0] = -1.0;
    toGlNdc[1][1] = -2.0;  // y down -> up: W - 2Y
    toGlNdc[3][1] = 1.0;
    const glm::dmat4 view =
        flipZ * glm::dmat4(glm::make_mat4(static_cast<const float*>(toCamera->data())));
    const glm::dmat4 projection = toGlNdc *
        glm::dmat4(glm::make_mat4(static_cast<const float*>(toNdc->data()))) * glm::inverse(view);
    const float* jitter =
        static_cast<const float*>(exr.spec.find_attribute("taa:jitter")->data());
    json << (f > 1 ? ", " : "") << "\"" << f << "\": {\"view\": [";
    for (int i = 0; i < 16; ++i) json << (i ? ", " : "") << glm::value_ptr(view)[i];
    json << "], \"projection\": [";
    for (int i = 0; i < 16; ++i) json << (i ? ", " : "") << glm::value_ptr(projection)[i];
    json << "], \"jitter\": [" << jitter[0] << ", " << jitter[1] << "]}";
  }
  json << "}}";
  json.close();

  for (const std::string mode : {"history", "window"}) {
    auto headers = separateArgs(in, mode + "_headers");
    headers.insert(headers.end(), {"--camera-motion", "camera", "--mode", mode});
    runOk(headers);
    auto sidecar = separateArgs(in, mode + "_sidecar");
    sidecar.insert(sidecar.end(), {"--camera-motion", "camera", "--camera-sidecar",
                                   (dir_ / "camera.json").string(), "--jitter", "sidecar",
                                   "--mode", mode});
    runOk(sidecar);
    // The window resolve gathers from every frame of its window from frame 1 on.
    expectSameOutput(mode + "_headers", mode + "_sidecar", kFrames, 1e-4f,
                     mode == "history" ? 2 : 0, 0.01);
  }
}

TEST_F(ConventionsTest, OutputKeepsNamesTypeMetadataAndPassThroughChannels) {
  const fs::path cycles = generate("cycles", layoutWriter(scenes::OutputLayout::Cycles),
                                   "moving_object", 32, 20, 2);
  const ToolRun r =
      run({"--preset", "cycles", (cycles / "render.####.exr").string(), "--passthrough",
           "ViewLayer.Vector.*,ViewLayer.Depth.Z", "--reset-frames", "2", "-o",
           (dir_ / "out.####.exr").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Exr in = readExr(cycles / frameName("render", 2));
  const Exr out = readExr(dir_ / frameName("out", 2));
  std::vector<std::string> names = out.spec.channelnames;
  std::sort(names.begin(), names.end());
  std::vector<std::string> inputNames = in.spec.channelnames;
  std::sort(inputNames.begin(), inputNames.end());
  EXPECT_EQ(names, inputNames);  // a drop-in replacement: the same channels
  EXPECT_EQ(out.spec.format, OIIO::TypeFloat);  // the input's type (float)
  EXPECT_EQ(out.spec.get_string_attribute("taa:scene"), "moving_object");  // metadata kept
  EXPECT_NE(out.spec.get_string_attribute("taa:version"), "");
  const std::string options = out.spec.get_string_attribute("taa:options");
  EXPECT_NE(options.find("blend=" + resolveOptionValue(ResolveOptions{}, "blend")),
            std::string::npos)
      << options;
  EXPECT_NE(options.find("rectify=" + resolveOptionValue(ResolveOptions{}, "rectify")),
            std::string::npos)
      << options;
  // Pass-through channels are the input's values, untouched.
  for (int c = 0; c < out.spec.nchannels; ++c) {
    const std::string& name = out.spec.channelnames[c];
    if (name.rfind("ViewLayer.Vector.", 0) != 0 && name != "ViewLayer.Depth.Z") continue;
    const int ic = in.spec.channelindex(name);
    ASSERT_GE(ic, 0) << name;
    for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
      ASSERT_EQ(out.pixels[p * out.spec.nchannels + c], in.pixels[p * in.spec.nchannels + ic])
          << name << " pixel " << p;
    }
  }

  const ToolRun renamed =
      run({"--preset", "cycles", (cycles / "render.####.exr").string(), "--out-ch", "R,G,B,A",
           "-d", "half", "--aov", "*=drop", "-o", (dir_ / "renamed.####.exr").string()});
  ASSERT_EQ(renamed.exitCode, 0) << renamed.err;
  const Exr half = readExr(dir_ / frameName("renamed", 1));
  EXPECT_EQ(half.spec.channelnames, (std::vector<std::string>{"R", "G", "B", "A"}));
  EXPECT_EQ(half.spec.format, OIIO::TypeHalf);
}

TEST_F(ConventionsTest, BadInputGivesClearErrors) {
  const fs::path cycles = generate("cycles", layoutWriter(scenes::OutputLayout::Cycles),
                                   "moving_object", 32, 20, 2);
  const std::string render = (cycles / "render.####.exr").string();
  const std::string out = (dir_ / "o" / "r.####.exr").string();
  // A preset expecting channels the file lacks: missing and available names (alpha is
  // optional: a file without it reads as opaque, so it is not among the missing).
  expectError(run({"--preset", "nuke", render, "-o", out}),
              {"lacks channels R, G, B;", "available: ViewLayer.Combined.R", "ViewLayer.Vector.X",
               "render.0001.exr", "frame 1"});
  expectError(run({"--preset", "nuke", render, "--color-ch",
                   "ViewLayer.Combined.R,ViewLayer.Combined.G,ViewLayer.Combined.B", "--depth-ch",
                   "ViewLayer.Depth.Z", "-o", out}),
              {"motion file lacks channels backward.u, backward.v", "ViewLayer.Vector.W",
               "channel backward.u, backward.v"});
  // A motion AOV with the wrong number of channels.
  expectError(run({"--preset", "cycles", render, "--motion-ch", "ViewLayer.Vector.X", "-o", out}),
              {"--motion-ch expects 2 channel names"});
  // An unreadable sidecar, and one missing a frame: nothing is written.
  std::ofstream(dir_ / "broken.json") << "{\"frames\": {\"1\": ";
  expectError(run({"--preset", "cycles", render, "--camera-sidecar",
                   (dir_ / "broken.json").string(), "-o", out}),
              {"not valid JSON", "broken.json"});
  std::ofstream(dir_ / "short.json") << R"({"frames": {"1": {"jitter": [0, 0]}}})";
  expectError(run({"--preset", "cycles", render, "--camera-sidecar",
                   (dir_ / "short.json").string(), "--jitter", "sidecar", "-o", out}),
              {"no entry", "short.json", "frame 2"});
  expectError(run({"--preset", "cycles", render, "--jitter", "header:nope", "-o", out}),
              {"no jitter attribute nope", "render.0001.exr", "frame 1"});
  expectError(run({"--preset", "blender", render, "-o", out}), {"blender", "cycles, nuke"});
  EXPECT_FALSE(fs::exists(dir_ / "o" / "r.0002.exr"));
}

}  // namespace
}  // namespace taa
