#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

#include "cli/cli_options.h"
#include "taa/error.h"

namespace taa::cli {
namespace {

std::string errorOf(const std::vector<std::string>& args) {
  try {
    parseCommandLine(args);
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(CliOptions, SeparateFilesWithChannels) {
  const CommandLine cl = parseCommandLine({"beauty.####.exr", "--depth", "depth.####.exr",
                                           "--motion", "mv.####.exr", "--motion-ch", "R,G",
                                           "--motion-y", "up", "-o", "out.####.exr", "-d",
                                           "float", "--compression", "piz", "--gl", "osmesa"});
  const auto& layout = cl.job.layout;
  EXPECT_EQ(layout.color.pattern, "beauty.####.exr");
  EXPECT_EQ(layout.color.channels, (std::vector<std::string>{"R", "G", "B", "A"}));
  ASSERT_TRUE(layout.depth && layout.motion);
  EXPECT_EQ(layout.depth->pattern, "depth.####.exr");
  EXPECT_EQ(layout.depth->channels, std::vector<std::string>{"Z"});
  EXPECT_EQ(layout.motion->channels, (std::vector<std::string>{"R", "G"}));
  EXPECT_TRUE(layout.motionConvention.yUp);
  EXPECT_EQ(cl.job.outputPattern, "out.####.exr");
  EXPECT_EQ(cl.job.write.pixelType, io::PixelType::Float);
  EXPECT_EQ(cl.job.write.compression, "piz");
  EXPECT_EQ(cl.job.backend, gl::Backend::OsMesa);
}

TEST(CliOptions, NoDepthOrMotionUnlessAsked) {
  const CommandLine cl = parseCommandLine({"b.#.exr", "-o", "o.#.exr"});
  EXPECT_FALSE(cl.job.layout.depth);
  EXPECT_FALSE(cl.job.layout.motion);
  const CommandLine withChannel = parseCommandLine({"b.#.exr", "--depth-ch", "depth.Z", "-o", "o"});
  ASSERT_TRUE(withChannel.job.layout.depth);
  EXPECT_EQ(withChannel.job.layout.depth->pattern, "");  // read from the color file
}

TEST(CliOptions, CyclesPresetWithOverride) {
  const CommandLine cl = parseCommandLine({"--preset", "cycles", "--layer", "RenderLayer",
                                           "r.####.exr", "--depth-ch", "RenderLayer.Mist.Z",
                                           "-o", "o.####.exr"});
  const auto& layout = cl.job.layout;
  EXPECT_EQ(layout.color.channels[0], "RenderLayer.Combined.R");
  ASSERT_TRUE(layout.depth && layout.motion);
  EXPECT_EQ(layout.depth->channels, std::vector<std::string>{"RenderLayer.Mist.Z"});
  EXPECT_EQ(layout.motion->channels,
            (std::vector<std::string>{"RenderLayer.Vector.X", "RenderLayer.Vector.Y"}));
  EXPECT_TRUE(layout.motionConvention.yUp);
}

TEST(CliOptions, ResolveAndJitterOptions) {
  const CommandLine cl =
      parseCommandLine({"b.#.exr", "-o", "o.#.exr", "--blend", "0.25", "--jitter-offset", "-1000",
                        "--jitter-period", "16", "--rectify", "clamp", "--box-space", "rgb",
                        "--motion-dilation", "centre", "--reset-frames", "5,9-10",
                        "--debug-layers", "-v"});
  EXPECT_FLOAT_EQ(cl.job.resolve.blend, 0.25f);
  EXPECT_EQ(cl.job.resolve.jitter.indexOffset, -1000);
  EXPECT_EQ(cl.job.resolve.jitter.period, 16);
  EXPECT_EQ(cl.job.resolve.rectify, Rectify::Clamp);
  EXPECT_EQ(cl.job.resolve.boxSpace, BoxSpace::RGB);
  EXPECT_EQ(cl.job.resolve.motionDilation, MotionDilation::Centre);
  EXPECT_EQ(cl.job.resetFrames, (std::set<int>{5, 9, 10}));
  EXPECT_TRUE(cl.job.debugLayers);
  EXPECT_EQ(cl.verbosity, Verbosity::Verbose);
}

TEST(CliOptions, BracketOptions) {
  const CommandLine cl = parseCommandLine({"b.#.exr", "-o", "o.#.exr", "--ocio-config", "c.ocio",
                                           "--colorspace-in", "acescg", "--bracket", "taa_log2",
                                           "--colorspace-out", "lin"});
  EXPECT_EQ(cl.job.resolve.color.ocioConfig, "c.ocio");
  EXPECT_EQ(cl.job.resolve.color.colorspaceIn, "acescg");
  EXPECT_EQ(cl.job.resolve.color.bracket, "taa_log2");
  EXPECT_EQ(cl.job.resolve.color.colorspaceOut, "lin");
  EXPECT_TRUE(parseCommandLine({"--list-brackets"}).listBrackets);
}

TEST(CliOptions, ErrorsNameTheArgument) {
  EXPECT_NE(errorOf({"b.#.exr", "--gl", "vulkan"}).find("vulkan"), std::string::npos);
  EXPECT_NE(errorOf({"b.#.exr", "--frobnicate"}).find("--frobnicate"), std::string::npos);
  EXPECT_NE(errorOf({"b.#.exr", "--blend", "2"}).find("blend"), std::string::npos);
  EXPECT_NE(errorOf({"b.#.exr", "--rectify", "soft"}).find("variance|clip|clamp|none"),
            std::string::npos);
  EXPECT_NE(errorOf({"b.#.exr", "--blend", "abc"}).find("abc"), std::string::npos);
  EXPECT_NE(errorOf({"b.#.exr", "-o"}).find("-o needs a value"), std::string::npos);
  EXPECT_NE(errorOf({"b.#.exr", "-d", "int8"}).find("int8"), std::string::npos);
  EXPECT_NE(errorOf({"-o", "x.exr"}).find("no color input"), std::string::npos);
  EXPECT_NE(errorOf({"b.#.exr", "--color-ch", "R,G"}).find("3 or 4"), std::string::npos);
}

TEST(CliOptions, HelpListsEveryOptionGroup) {
  const std::string help = helpText();
  for (const char* text : {"--frames", "-o PATTERN", "--depth", "--motion", "--preset cycles",
                           "--jitter", "--blend", "-d half|float", "--compression", "--gl",
                           "--info", "-v"}) {
    EXPECT_NE(help.find(text), std::string::npos) << text;
  }
}

TEST(CliOptions, ReadmeTableIsTheRegistry) {
  std::ifstream readme(TAA_SOURCE_DIR "/README.md");
  std::stringstream text;
  text << readme.rdbuf();
  const std::string s = text.str();
  const std::string begin = "<!-- options:begin -->\n", end = "<!-- options:end -->";
  const auto from = s.find(begin), to = s.find(end);
  ASSERT_NE(from, std::string::npos);
  ASSERT_NE(to, std::string::npos);
  EXPECT_EQ(s.substr(from + begin.size(), to - from - begin.size()), optionsMarkdownTable())
      << "regenerate the README table with: taatool --list-options";
}

}  // namespace
}  // namespace taa::cli

namespace taa::cli {
namespace {

// Issue 24: an option that changes nothing is an error naming it and what it needs; before,
// "--layer RL" without --preset cycles was ignored without a word.
TEST(CliOptions, OptionsWithoutEffectAreErrors) {
  const std::vector<std::string> plain = {"b.#.exr", "-o", "o.#.exr"};
  auto with = [&](std::vector<std::string> extra) {
    std::vector<std::string> args = plain;
    args.insert(args.end(), extra.begin(), extra.end());
    return args;
  };
  auto fails = [&](std::vector<std::string> extra, const std::string& fragment) {
    const std::string message = errorOf(with(extra));
    EXPECT_NE(message.find(fragment), std::string::npos) << message;
  };
  fails({"--layer", "RL"}, "--layer has no effect without --preset cycles");
  fails({"--preset", "nuke", "--layer", "RL"}, "--layer has no effect without --preset cycles");
  fails({"--motion-y", "up"}, "--motion-y has no effect without motion vectors");
  fails({"--depth-kind", "radial"}, "--depth-kind has no effect without depth");
  fails({"--motion", "m.#.exr", "--motion-max", "2"},
        "--motion-max has no effect without --motion-encoding centred");
  fails({"--depth", "d.#.exr", "--depth-near", "0.5"},
        "--depth-near has no effect without --depth-kind ndc or reversed-z");
  fails({"--depth", "d.#.exr", "--depth-fov", "40"},
        "--depth-fov has no effect without --depth-kind radial");
  fails({"--jitter", "none", "--jitter-offset", "3"},
        "--jitter-offset has no effect when the jitter is not Halton's");
  fails({"--jitter", "sidecar", "--camera-sidecar", "c.json", "--jitter-period", "8"},
        "--jitter-period has no effect");

  // With what they need, each takes effect.
  for (const auto& extra : std::vector<std::vector<std::string>>{
           {"--preset", "cycles", "--layer", "RL"},
           {"--preset", "nuke", "--motion-y", "down", "--depth-nohit", "5"},
           {"--motion", "m.#.exr", "--motion-encoding", "centred", "--motion-max", "2"},
           {"--preset", "unreal", "--motion-max", "0.5"},  // the preset's encoding is centred
           {"--depth-ch", "Z", "--depth-kind", "reversed-z", "--depth-far", "inf"},
           {"--depth", "d.#.exr", "--depth-kind", "radial", "--depth-fov", "40"},
           {"--jitter-offset", "3", "--jitter-scale", "0.5"}}) {
    EXPECT_EQ(errorOf(with(extra)), "") << extra[0];
  }
}

}  // namespace
}  // namespace taa::cli
