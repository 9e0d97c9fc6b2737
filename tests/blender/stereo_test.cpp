// A Blender stereo render (issue 24): Cycles writes one multi-view EXR a frame (multiView
// left, right; ViewLayer.Combined.left.R ...). taatool --preset cycles resolves both views in
// one run and writes them back as one multi-view file, each view bit for bit what resolving it
// alone (--view NAME) gives, in both modes; in window mode each view's passes too (issue 21).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "../e2e/taatool_runner.h"
#include "blender_tmpdir.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

constexpr int kFrames = 5;

// Renders the stereo scene once per test process, into a folder of its own.
const fs::path& renderedStereo() {
  static const fs::path dir = [] {
    const fs::path out = fs::path(TAA_TEST_TMPDIR) / ("stereo_" + std::to_string(getpid()));
    fs::remove_all(out);
    fs::create_directories(out);
    test::keepBlendersTemporaryFilesInTheTestFolder();
    const std::string command = "blender -b --factory-startup -noaudio -P '" +
                                std::string(TAA_STEREO_SCENE_SCRIPT) + "' -- '" + out.string() +
                                "' > '" + (out / "blender.log").string() + "' 2>&1";
    if (std::system(command.c_str()) != 0) {
      ADD_FAILURE() << "Blender failed (Debian's blender is installed by "
                       "scripts/install-deps.sh); see " << (out / "blender.log");
    }
    return out;
  }();
  return dir;
}

struct Exr {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;
  std::vector<float> channel(const std::string& name) const {
    std::vector<float> values;
    int c = 0;
    while (c < spec.nchannels && spec.channelnames[std::size_t(c)] != name) ++c;
    EXPECT_LT(c, spec.nchannels) << name;
    if (c == spec.nchannels) return values;
    for (std::size_t p = 0; p < spec.image_pixels(); ++p) {
      values.push_back(pixels[p * std::size_t(spec.nchannels) + std::size_t(c)]);
    }
    return values;
  }
};

Exr readExr(const fs::path& path) {
  Exr exr;
  auto in = OIIO::ImageInput::open(path.string());
  EXPECT_TRUE(in) << path;
  if (!in) return exr;
  exr.spec = in->spec();
  exr.pixels.resize(exr.spec.image_pixels() * std::size_t(exr.spec.nchannels));
  EXPECT_TRUE(in->read_image(0, 0, 0, exr.spec.nchannels, OIIO::TypeFloat, exr.pixels.data()));
  return exr;
}

std::vector<std::string> multiView(const OIIO::ImageSpec& spec) {
  std::vector<std::string> views;
  if (const OIIO::ParamValue* value = spec.find_attribute("multiView")) {
    for (std::size_t i = 0; i < value->type().numelements(); ++i) {
      views.emplace_back(static_cast<const char* const*>(value->data())[i]);
    }
  }
  return views;
}

std::string frameName(int frame) {
  char name[32];
  std::snprintf(name, sizeof name, "r_%04d.exr", frame);
  return name;
}

// One view of a one-part multi-view frame as a file of that view alone would hold it: its
// channels with the view taken out of their names, in their types, no multiView attribute.
Exr viewAlone(const Exr& input, const std::string& view) {
  const std::string tag = "." + view + ".";
  Exr alone;
  alone.spec = input.spec;
  alone.spec.erase_attribute("multiView");
  alone.spec.channelnames.clear();
  alone.spec.channelformats.clear();
  std::vector<int> picked;
  for (int c = 0; c < input.spec.nchannels; ++c) {
    std::string name = input.spec.channelnames[std::size_t(c)];
    const std::size_t at = name.find(tag);
    if (at == std::string::npos) continue;
    picked.push_back(c);
    alone.spec.channelnames.push_back(name.erase(at, view.size() + 1));
    alone.spec.channelformats.push_back(input.spec.channelformat(c));
  }
  alone.spec.nchannels = int(picked.size());
  for (std::size_t p = 0; p < input.spec.image_pixels(); ++p) {
    for (int c : picked) {
      alone.pixels.push_back(input.pixels[p * std::size_t(input.spec.nchannels) + std::size_t(c)]);
    }
  }
  return alone;
}

class StereoTest : public ::testing::TestWithParam<std::string> {};

TEST_P(StereoTest, BothViewsInOneRunEachAsIfAlone) {
  const fs::path& render = renderedStereo();
  const Exr input = readExr(render / "render_0001.exr");
  ASSERT_EQ(multiView(input.spec), (std::vector<std::string>{"left", "right"}));
  const std::string mode = GetParam();
  const fs::path dir = test::freshTestFolder();
  auto run = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = {"--preset", "cycles", (render / "render_####.exr").string(),
                                     "--mode", mode, "-q", "-o",
                                     (dir / out / "r_####.exr").string()};
    args.insert(args.end(), extra.begin(), extra.end());
    const test::ToolRun r = test::runTaatool(args, dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
  };
  run("both", {});
  run("left", {"--view", "left"});
  run("right", {"--view", "right"});
  for (int frame = 1; frame <= kFrames; ++frame) {
    const Exr both = readExr(dir / "both" / frameName(frame));
    EXPECT_EQ(multiView(both.spec), (std::vector<std::string>{"left", "right"}));
    // The views are part of the options a resumed farm run compares.
    const std::string options = both.spec.get_string_attribute("taa:options");
    EXPECT_NE(options.find("; views=left,right"), std::string::npos) << options;
    for (const std::string view : {"left", "right"}) {
      const Exr alone = readExr(dir / view / frameName(frame));
      EXPECT_EQ(multiView(alone.spec), std::vector<std::string>{view});
      EXPECT_NE(alone.spec.get_string_attribute("taa:options").find("; views=" + view),
                std::string::npos);
      // Its colour, and in window mode its passes: its own channels only, each as in both.
      EXPECT_EQ(alone.spec.nchannels, mode == "window" ? 16 : 4);
      for (const std::string& name : alone.spec.channelnames) {
        EXPECT_NE(name.find("." + view + "."), std::string::npos) << name;
        EXPECT_EQ(both.channel(name), alone.channel(name)) << name << " frame " << frame;
      }
      EXPECT_EQ(both.spec.channelformat(0), OIIO::TypeHalf);  // the render's half colour
    }
    // The views differ (the eyes see the cube from two places): the comparison can fail.
    EXPECT_NE(both.channel("ViewLayer.Combined.left.R"),
              both.channel("ViewLayer.Combined.right.R"));
  }
}

INSTANTIATE_TEST_SUITE_P(Modes, StereoTest, ::testing::Values("window", "history"));

TEST(StereoViews, ViewChoicesAreChecked) {
  const fs::path& render = renderedStereo();
  const fs::path dir = test::freshTestFolder();
  const std::vector<std::string> base = {"--preset", "cycles",
                                         (render / "render_####.exr").string(), "-o",
                                         (dir / "r_####.exr").string()};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = base;
    args.insert(args.end(), extra.begin(), extra.end());
    return test::runTaatool(args, dir);
  };
  test::expectToolError(with({"--view", "centre"}),
                        {"the color file has no view centre (its views: left, right)",
                         "render_0001.exr"});
  test::expectToolError(with({"--debug-layers"}),
                        {"--debug-layers shows one view", "pick one with --view"});
}

// Each view's passes (issue 21) are its own channels, resolved with its own weights: the
// multi-view run's channels of a view are what a file of that view alone (the view taken out
// of the names, no multiView) resolves to, bit for bit, kinds included (DiffDir.left.R is a
// DiffDir, summed with its DiffCol).
TEST(StereoPasses, EachViewResolvesItsOwnPassesAsAFileOfItAlone) {
  const fs::path& render = renderedStereo();
  const fs::path dir = test::freshTestFolder();
  auto run = [&](const fs::path& input, const std::string& out) {
    const test::ToolRun r = test::runTaatool(
        {"--preset", "cycles", input.string(), "-q", "-o", (dir / out / "r_####.exr").string()},
        dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
  };
  run(render / "render_####.exr", "both");
  for (const std::string view : {"left", "right"}) {
    const std::string tag = "." + view + ".";
    for (int frame = 1; frame <= kFrames; ++frame) {
      const Exr alone = viewAlone(readExr(render / ("render_" + frameName(frame).substr(2))), view);
      const fs::path path = dir / ("in_" + view) / frameName(frame);
      fs::create_directories(path.parent_path());
      auto out = OIIO::ImageOutput::create(path.string());
      ASSERT_TRUE(out && out->open(path.string(), alone.spec));
      ASSERT_TRUE(out->write_image(OIIO::TypeFloat, alone.pixels.data()));
      ASSERT_TRUE(out->close());
    }
    run(dir / ("in_" + view) / "r_####.exr", "alone_" + view);
    for (int frame = 1; frame <= kFrames; ++frame) {
      const Exr both = readExr(dir / "both" / frameName(frame));
      const Exr alone = readExr(dir / ("alone_" + view) / frameName(frame));
      // Colour and 12 pass channels a view (depth, vectors, DiffDir, DiffCol, IndexOB).
      EXPECT_EQ(alone.spec.nchannels, 16);
      EXPECT_EQ(both.spec.nchannels, 32);
      for (const std::string& name : alone.spec.channelnames) {
        const std::string named = name.substr(0, name.rfind('.')) + tag.substr(0, tag.size() - 1) +
                                  name.substr(name.rfind('.'));
        EXPECT_EQ(both.channel(named), alone.channel(name)) << named << " frame " << frame;
      }
    }
  }
  // The passes are resolved, not copied: the comparison can fail.
  const Exr raw = readExr(render / "render_0003.exr");
  const Exr both = readExr(dir / "both" / frameName(3));
  EXPECT_NE(both.channel("ViewLayer.DiffCol.right.R"), raw.channel("ViewLayer.DiffCol.right.R"));
}

// The same render as a file of one part per view (OpenEXR's other multi-view convention, as
// Nuke writes it): each view's channels without the view, in a part with a `view` attribute.
// Both views resolve in one run, with their passes, and come out as one multi-view part: the
// first view's channels under the part's names, the other's with the view in them. Each value
// is what the one-part file gives the same channel, bit for bit.
TEST(StereoParts, AFileOfOnePartPerViewResolvesEveryViewWithItsPasses) {
  const fs::path& render = renderedStereo();
  const fs::path dir = test::freshTestFolder();
  const std::vector<std::string> views = {"left", "right"};
  for (int frame = 1; frame <= kFrames; ++frame) {
    const Exr input = readExr(render / ("render_" + frameName(frame).substr(2)));
    std::vector<OIIO::ImageSpec> specs;
    std::vector<std::vector<float>> parts;
    for (const std::string& view : views) {
      Exr alone = viewAlone(input, view);
      alone.spec.attribute("view", view);
      alone.spec.attribute("name", "ViewLayer." + view);
      specs.push_back(alone.spec);
      parts.push_back(std::move(alone.pixels));
    }
    const fs::path path = dir / "parts" / frameName(frame);
    fs::create_directories(path.parent_path());
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), int(specs.size()), specs.data()));
    for (std::size_t part = 0; part < specs.size(); ++part) {
      if (part > 0) {
        ASSERT_TRUE(out->open(path.string(), specs[part], OIIO::ImageOutput::AppendSubimage));
      }
      ASSERT_TRUE(out->write_image(OIIO::TypeFloat, parts[part].data()));
    }
    ASSERT_TRUE(out->close());
  }
  auto run = [&](const fs::path& input, const std::string& out) {
    const test::ToolRun r = test::runTaatool(
        {"--preset", "cycles", input.string(), "-q", "-o", (dir / out / "r_####.exr").string()},
        dir);
    EXPECT_EQ(r.exitCode, 0) << r.err;
  };
  run(dir / "parts" / "r_####.exr", "from_parts");
  run(render / "render_####.exr", "from_one_part");
  for (int frame = 1; frame <= kFrames; ++frame) {
    const Exr parts = readExr(dir / "from_parts" / frameName(frame));
    const Exr onePart = readExr(dir / "from_one_part" / frameName(frame));
    EXPECT_EQ(multiView(parts.spec), views);
    // Colour and 12 pass channels a view.
    EXPECT_EQ(parts.spec.nchannels, 32);
    for (const std::string& name : onePart.spec.channelnames) {
      // "ViewLayer.DiffDir.left.R" is the first view's: "ViewLayer.DiffDir.R" in the output of
      // the parts; the right view's names are the same in both.
      std::string named = name;
      if (const std::size_t at = named.find(".left."); at != std::string::npos) {
        named.erase(at, 5);
      }
      EXPECT_EQ(parts.channel(named), onePart.channel(name)) << named << " frame " << frame;
    }
  }
  // The right view's passes are resolved, not copied: the comparison can fail.
  const Exr raw = readExr(render / "render_0003.exr");
  const Exr parts = readExr(dir / "from_parts" / frameName(3));
  EXPECT_NE(parts.channel("ViewLayer.DiffCol.right.R"), raw.channel("ViewLayer.DiffCol.right.R"));
}

}  // namespace
}  // namespace taa
