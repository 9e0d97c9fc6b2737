// End-to-end: input that changes the result is reported with counts or, with --strict, refused;
// gaps, descending ranges and bad values are errors naming file, frame and channel (issue 17).
#include <gtest/gtest.h>

#include <OpenImageIO/imageio.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <limits>

#include "io/output_completeness.h"
#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

using test::ToolRun;

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();

// Rewrites the EXR at `path` as float with `edit` applied to its header and pixels (interleaved).
void rewriteExr(const fs::path& path,
                const std::function<void(OIIO::ImageSpec&, std::vector<float>&)>& edit) {
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in) << path;
  OIIO::ImageSpec spec = in->spec();
  std::vector<float> pixels(spec.image_pixels() * std::size_t(spec.nchannels));
  ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, pixels.data()));
  in.reset();
  spec.set_format(OIIO::TypeFloat);
  spec.channelformats.clear();
  edit(spec, pixels);
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
  ASSERT_TRUE(out->close());
}

class InputPolicyTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder();
    in_ = dir_ / "in";
    test::writeSeparateFrames(in_, 1, 6);
  }

  ToolRun run(std::vector<std::string> extra) const {
    std::vector<std::string> args = test::separateFileArgs(in_, dir_ / "out" / "r.####.exr");
    args.insert(args.end(), extra.begin(), extra.end());
    return test::runTaatool(args, dir_);
  }
  bool written(int frame) const {
    char name[32];
    std::snprintf(name, sizeof name, "r.%04d.exr", frame);
    return fs::exists(dir_ / "out" / name);
  }
  static bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
  }

  fs::path dir_, in_;
};

// Defect 5: a missing frame in the middle was skipped silently without --frames.
TEST_F(InputPolicyTest, AGapInTheSequenceIsAnErrorUnlessSkipMissing) {
  fs::remove(in_ / "beauty.0004.exr");
  test::expectToolError(run({}), {"1 frame missing from the sequence 1-6: 4", "--skip-missing",
                                  (in_ / "beauty.0004.exr").string(), "frame 4"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));  // refused before any frame is written

  const ToolRun skipped = run({"--skip-missing"});
  ASSERT_EQ(skipped.exitCode, 0) << skipped.err;
  for (int frame : {1, 2, 3, 5, 6}) EXPECT_TRUE(written(frame)) << frame;
  EXPECT_FALSE(written(4));
  EXPECT_TRUE(contains(skipped.err, "taatool WARNING: skipped 1 missing frame (4): history "
                                    "restarts after each gap"))
      << skipped.err;

  fs::remove(in_ / "beauty.0002.exr");
  test::expectToolError(run({"--skip-missing", "--strict"}),
                        {"2 frames missing from the sequence: 2, 4 (--strict: not skipped)",
                         (in_ / "beauty.0002.exr").string(), "frame 2"});
}

// Issue 25: --skip-missing did nothing with --frames; the missing frame was an error.
TEST_F(InputPolicyTest, SkipMissingWorksWithFrames) {
  fs::remove(in_ / "beauty.0004.exr");
  test::expectToolError(run({"--frames", "2-5"}), {(in_ / "beauty.0004.exr").string()});
  const ToolRun skipped = run({"--frames", "2-5", "--skip-missing"});
  ASSERT_EQ(skipped.exitCode, 0) << skipped.err;
  for (int frame : {2, 3, 5}) EXPECT_TRUE(written(frame)) << frame;
  EXPECT_FALSE(written(4));
  EXPECT_FALSE(written(1));
  EXPECT_TRUE(contains(skipped.err, "skipped 1 missing frame (4)")) << skipped.err;
  test::expectToolError(run({"--frames", "4", "--skip-missing"}), {"none of the frames 4 exists"});
}

// Issue 25: a dangling link and a loop of links were reported as "missing input frame".
TEST_F(InputPolicyTest, ABrokenLinkIsNamedAsSuch) {
  fs::remove(in_ / "depth.0003.exr");
  fs::create_symlink(in_ / "gone.exr", in_ / "depth.0003.exr");
  test::expectToolError(run({}), {"input frame is a symbolic link to " +
                                      (in_ / "gone.exr").string() + ", which does not exist",
                                  (in_ / "depth.0003.exr").string(), "frame 3"});
  fs::remove(in_ / "depth.0003.exr");
  fs::create_symlink(in_ / "depth.0003.exr", in_ / "depth.0003.exr");
  test::expectToolError(run({}), {"input frame is a loop of symbolic links",
                                  (in_ / "depth.0003.exr").string()});
}

// Defect 6: --frames 5-1 ran backwards, history reset on every frame, exit 0.
TEST_F(InputPolicyTest, DescendingFramesAreAnError) {
  test::expectToolError(run({"--frames", "5-1"}), {"frames must ascend: 4 follows 5"});
  test::expectToolError(run({"--frames", "3,1-2"}), {"frames must ascend: 1 follows 3"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

// Cut detection is a history-mode stage: asked for in window mode it is an error, not ignored.
TEST_F(InputPolicyTest, CutDetectionInWindowModeIsAnError) {
  test::expectToolError(run({"--mode", "window", "--cut-detection", "0.5"}),
                        {"--cut-detection is a history-mode stage", "--reset-frames"});
  EXPECT_FALSE(fs::exists(dir_ / "out"));
}

TEST_F(InputPolicyTest, NonFiniteColourAndMotionAreReportedWithCountsOrRefusedWhenStrict) {
  rewriteExr(in_ / "beauty.0003.exr", [](OIIO::ImageSpec&, std::vector<float>& p) {
    p[0] = p[5] = p[10] = kNaN;
  });
  rewriteExr(in_ / "beauty.0005.exr", [](OIIO::ImageSpec&, std::vector<float>& p) {
    p[7] = std::numeric_limits<float>::infinity();
  });
  rewriteExr(in_ / "motion.0002.exr", [](OIIO::ImageSpec&, std::vector<float>& p) {
    p[1] = kNaN;
  });
  const ToolRun lenient = run({});
  ASSERT_EQ(lenient.exitCode, 0) << lenient.err;
  EXPECT_TRUE(contains(lenient.err, "taatool WARNING: set 4 NaN/Inf colour values to 0 in 2 "
                                    "frames (first: frame 3, " +
                                        (in_ / "beauty.0003.exr").string() + ")"))
      << lenient.err;
  EXPECT_TRUE(contains(lenient.err, "taatool WARNING: set 1 NaN/Inf motion value to 0 in 1 frame "
                                    "(first: frame 2, " +
                                        (in_ / "motion.0002.exr").string() + ")"))
      << lenient.err;

  fs::remove_all(dir_ / "out");
  test::expectToolError(run({"--strict"}), {"1 NaN/Inf motion value would be set to 0 (--strict)",
                                            (in_ / "motion.0002.exr").string(), "frame 2",
                                            "channel X, Y"});
  EXPECT_TRUE(written(1));
  EXPECT_FALSE(written(2));  // nothing of the refused frame
  test::expectToolError(run({"--strict", "--frames", "3-6"}),
                        {"3 NaN/Inf colour values would be set to 0 (--strict)",
                         (in_ / "beauty.0003.exr").string(), "frame 3", "channel R, G, B, A"});
}

TEST_F(InputPolicyTest, ASizeChangeIsReportedOrRefusedWhenStrict) {
  test::writeSeparateFrames(in_, 4, 4, 32, 20);  // frame 4 rendered at another size
  const ToolRun lenient = run({"-v", "--mode", "history"});
  ASSERT_EQ(lenient.exitCode, 0) << lenient.err;
  EXPECT_TRUE(contains(lenient.err, "taatool WARNING: the image size changed 2 times, history "
                                    "restarted there (first: frame 4, 32x20 after 64x40, " +
                                        (in_ / "beauty.0004.exr").string() + ")"))
      << lenient.err;
  EXPECT_TRUE(contains(lenient.out, "[new size 32x20: history reset]")) << lenient.out;
  test::expectToolError(run({"--strict", "--mode", "history"}),
                        {"the image size changes from 64x40 to 32x20, which restarts history "
                         "(--strict)",
                         (in_ / "beauty.0004.exr").string(), "frame 4"});
  // The window resolve (the default) cannot gather across sizes: an error naming the way out.
  test::expectToolError(run({}), {"frame is 32x20 but the frames of its window are 64x40",
                                  "--reset-frames", (in_ / "beauty.0004.exr").string(),
                                  "frame 4"});
  EXPECT_EQ(run({"--reset-frames", "4,5"}).exitCode, 0);  // frame 4 alone at 32x20
}

TEST_F(InputPolicyTest, FloatColourBeyondHalfForAHalfOutputIsReported) {
  rewriteExr(in_ / "beauty.0002.exr", [](OIIO::ImageSpec&, std::vector<float>& p) {
    p[0] = 1e6f;
    p[4] = -70000.0f;
  });
  const ToolRun r = run({"-d", "half", "--frames", "1-3"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(contains(r.err, "taatool WARNING: read 2 colour values beyond half float's range "
                              "for a half output (results beyond +-65504 are clamped to it) in 1 "
                              "frame (first: frame 2"))
      << r.err;
  auto out = OIIO::ImageInput::open((dir_ / "out" / "r.0002.exr").string());
  ASSERT_TRUE(out);
  std::vector<float> pixels(out->spec().image_pixels() * 4);
  ASSERT_TRUE(out->read_image(0, 0, 0, 4, OIIO::TypeFloat, pixels.data()));
  for (float v : pixels) ASSERT_TRUE(std::isfinite(v));
  EXPECT_EQ(run({"-d", "float", "--frames", "1-3", "--strict"}).exitCode, 0);  // nothing clamped
}

// Defect 3: a NaN jitter from a header attribute turned the whole frame into +Inf, exit 0.
TEST_F(InputPolicyTest, NonFiniteHeaderJitterIsAnError) {
  for (int frame = 1; frame <= 3; ++frame) {
    char name[32];
    std::snprintf(name, sizeof name, "beauty.%04d.exr", frame);
    rewriteExr(in_ / name, [frame](OIIO::ImageSpec& spec, std::vector<float>&) {
      const float jitter[2] = {frame == 2 ? kNaN : 0.25f, -0.25f};
      spec.attribute("taa:jitter", OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, OIIO::TypeDesc::VEC2),
                     jitter);
    });
  }
  for (const std::string mode : {"history", "window"}) {
    fs::remove_all(dir_ / "out");
    test::expectToolError(
        run({"--jitter", "header:taa:jitter", "--frames", "1-3", "--mode", mode}),
        {"jitter (nan, -0.25) from the header attribute taa:jitter is not a finite number of "
         "pixels",
         (in_ / "beauty.0002.exr").string(), "frame 2"});
    EXPECT_EQ(written(1), mode == "history");  // frame 1's window holds frame 2
    EXPECT_FALSE(written(2));
  }
}

TEST_F(InputPolicyTest, AbsurdThreadCountsAreRefused) {
  test::expectToolError(run({"--threads", "1000"}), {"--threads expects an integer from 0 to 16",
                                                     "\"1000\""});
  test::expectToolError(run({"--threads", "-1"}), {"--threads"});
}

// Item 9: a file that cannot be opened was reported as "not an OpenEXR file".
TEST_F(InputPolicyTest, AnUnreadableFileSaysWhy) {
  const fs::path victim = in_ / "depth.0002.exr";
  fs::permissions(victim, fs::perms::none);
  fs::create_directories(dir_ / "out");
  fs::permissions(dir_ / "out", fs::perms::all);
  std::vector<std::string> prefix;
  if (::geteuid() == 0) {
    // Root reads anything: run as nobody, for whom the file is unreadable (util-linux setpriv).
    prefix = {"--reuid=65534", "--regid=65534", "--clear-groups", test::taatoolPath()};
  }
  std::vector<std::string> args = test::separateFileArgs(in_, dir_ / "out" / "r.####.exr");
  args.insert(args.end(), {"--frames", "1-3"});
  ToolRun r;
  if (prefix.empty()) {
    r = test::runTaatool(args, dir_);
  } else {
    args.insert(args.begin(), prefix.begin(), prefix.end());
    fs::permissions(dir_, fs::perms::all);  // nobody writes stdout/stderr there
    r = test::runProgram("/usr/bin/setpriv", args, dir_);
  }
  test::expectToolError(r, {"cannot read the depth file: Permission denied",
                            victim.string(), "frame 2"});
  EXPECT_FALSE(contains(r.err, "OpenEXR")) << r.err;
  fs::permissions(victim, fs::perms::owner_read | fs::perms::owner_write);
}

}  // namespace
}  // namespace taa
