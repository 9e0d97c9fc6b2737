// End-to-end: every pass of the colour file resolved beside the beauty (issue 21). The scene
// generator's moving object gets light, factor, normal and index passes built per sample so
// that the comp's identity Combined = DiffDir x DiffCol + GlossDir x GlossCol + Emit holds in
// the input; taatool must keep it in the output, keep data passes unblended, and keep names and
// types.
#include <gtest/gtest.h>

#include <Imath/half.h>
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "taa/taa.h"
#include "taatool_runner.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

using test::Exr;
using test::frameName;
using test::readExr;
using test::ToolRun;

constexpr int kWidth = 64, kHeight = 40, kFrames = 6;

// Two Cryptomatte IDs (hashes stored as floats): the object where red outweighs green, and the
// rest.
constexpr float kIdRed = 1.5e-3f, kIdOther = -7.25e10f;

const std::vector<std::string> kLightPasses = {"DiffDir", "GlossDir", "Emit"};
const std::vector<std::string> kRgb = {"R", "G", "B"};

// The relative L1 mismatch of the comp identity over the image, in percent.
double identityMismatch(const Exr& beauty, const Exr& passes) {
  double error = 0.0, total = 0.0;
  for (std::size_t p = 0; p < beauty.spec.image_pixels(); ++p) {
    for (const std::string& c : kRgb) {
      const double rebuilt = double(passes.at(p, "DiffDir." + c)) * passes.at(p, "DiffCol." + c) +
                             double(passes.at(p, "GlossDir." + c)) * passes.at(p, "GlossCol." + c) +
                             passes.at(p, "Emit." + c);
      error += std::abs(double(beauty.at(p, c)) - rebuilt);
      total += std::abs(double(beauty.at(p, c)));
    }
  }
  return 100.0 * error / total;
}

class PassesTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTestFolder();
    in_ = dir_ / "in";
    test::writeSeparateFrames(in_, 1, kFrames, kWidth, kHeight);
    for (int f = 1; f <= kFrames; ++f) addPasses(in_ / frameName("beauty", f));
  }

  // Rewrites a beauty file with passes made from its own samples, per sample exact: a diffuse
  // colour that varies with the sample, light split 60/30/10 between diffuse, gloss and
  // emission, a normal, an object index; half colour, float data, as Cycles writes them.
  static void addPasses(const fs::path& path) {
    const Exr in = readExr(path);
    OIIO::ImageSpec spec(in.spec.width, in.spec.height, 0, OIIO::TypeHalf);
    std::vector<std::string> names = {"R", "G", "B", "A"};
    for (const std::string pass : {"DiffDir", "DiffCol", "GlossDir", "GlossCol", "Emit"}) {
      for (const std::string& c : kRgb) names.push_back(pass + "." + c);
    }
    for (const char* c : {"Normal.X", "Normal.Y", "Normal.Z", "IndexOB.X", "MatteRed.R"}) {
      names.push_back(c);
    }
    for (const char* layer : {"CryptoObject00.", "CryptoObject01."}) {
      for (const char* c : {"r", "g", "b", "a"}) names.push_back(layer + std::string(c));
    }
    spec.nchannels = int(names.size());
    spec.channelnames = names;
    spec.alpha_channel = 3;
    for (const std::string& name : names) {
      const bool data = name.rfind("Normal", 0) == 0 || name.rfind("IndexOB", 0) == 0 ||
                        name.rfind("Crypto", 0) == 0 || name.rfind("Matte", 0) == 0;
      spec.channelformats.push_back(data ? OIIO::TypeFloat : OIIO::TypeHalf);
    }
    std::vector<float> pixels;
    for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
      const float r = in.at(p, "R"), g = in.at(p, "G"), b = in.at(p, "B");
      const float rgb[3] = {r, g, b};
      const float diffuseColour = 0.25f + 0.5f * (0.5f + 0.5f * std::sin(13.0f * (r + 2.0f * g)));
      for (int c = 0; c < 4; ++c) pixels.push_back(c < 3 ? rgb[c] : in.at(p, "A"));
      for (int c = 0; c < 3; ++c) pixels.push_back(0.6f * rgb[c] / diffuseColour);
      for (int c = 0; c < 3; ++c) pixels.push_back(diffuseColour);
      for (int c = 0; c < 3; ++c) pixels.push_back(0.3f * rgb[c] / 0.5f);
      for (int c = 0; c < 3; ++c) pixels.push_back(0.5f);
      for (int c = 0; c < 3; ++c) pixels.push_back(0.1f * rgb[c]);
      // A normal that turns with the colour: averaging shortens it.
      const float angle = 6.0f * (r - b);
      pixels.push_back(std::cos(angle));
      pixels.push_back(std::sin(angle));
      pixels.push_back(0.0f);
      pixels.push_back(r > g ? 2.0f : 1.0f);
      // The red object's matte as a light pass, and as Cryptomatte: one ID a sample, coverage
      // 1 (one sample a pixel), the second pair and the second rank layer empty.
      pixels.push_back(r > g ? 1.0f : 0.0f);
      for (float v : {r > g ? kIdRed : kIdOther, 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}) {
        pixels.push_back(v);
      }
    }
    spec.attribute("cryptomatte/f834d0a/name", "CryptoObject");
    spec.attribute("cryptomatte/f834d0a/hash", "MurmurHash3_32");
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
    ASSERT_TRUE(out->close());
  }

  // Frame f of another input in `folder`: `spec` and `pixels` as its beauty, in_'s depth and
  // motion beside it.
  void writeFrameInto(const fs::path& folder, int f, const OIIO::ImageSpec& spec,
                      const std::vector<float>& pixels) const {
    const fs::path path = folder / frameName("beauty", f);
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
    ASSERT_TRUE(out->close());
    for (const char* aov : {"depth", "motion"}) {
      fs::copy_file(in_ / frameName(aov, f), folder / frameName(aov, f));
    }
  }

  ToolRun run(std::vector<std::string> extra, const std::string& out = "out") const {
    std::vector<std::string> args =
        test::separateFileArgs(in_, dir_ / out / "r.####.exr");
    args.insert(args.end(), extra.begin(), extra.end());
    return test::runTaatool(args, dir_);
  }

  fs::path dir_, in_;
};

TEST_F(PassesTest, EveryPassIsResolvedAndTheCompIdentityHolds) {
  const ToolRun r = run({"-v"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  // -v: a line a kind, its channels in file order.
  EXPECT_NE(r.err.find("passes resolved beside the colour, light: DiffDir.R, DiffDir.G"),
            std::string::npos)
      << r.err;
  EXPECT_NE(r.err.find("passes resolved beside the colour, nearest: IndexOB.X"),
            std::string::npos)
      << r.err;
  const int f = 3;
  const Exr in = readExr(in_ / frameName("beauty", f));
  const Exr out = readExr(dir_ / "out" / frameName("r", f));
  // A drop-in replacement: every channel under its name, in its type.
  std::multiset<std::string> inNames(in.spec.channelnames.begin(), in.spec.channelnames.end());
  std::multiset<std::string> outNames(out.spec.channelnames.begin(), out.spec.channelnames.end());
  EXPECT_EQ(outNames, inNames);
  for (const char* name : {"DiffDir.R", "Normal.X", "IndexOB.X"}) {
    EXPECT_EQ(out.spec.channelformat(out.spec.channelindex(name)),
              in.spec.channelformat(in.spec.channelindex(name)))
        << name;
  }

  // The identity holds in the input (to half's rounding), and in the output as well; the raw
  // passes beside the resolved beauty (what --passthrough gives) break it.
  const double input = identityMismatch(in, in);
  const double output = identityMismatch(out, out);
  const double passthrough = identityMismatch(out, in);
  EXPECT_LT(input, 0.1);
  EXPECT_LT(output, 0.5) << "input " << input << "%, passthrough " << passthrough << "%";
  EXPECT_GT(passthrough, 4.0 * output) << "output " << output << "%";
  std::printf("comp identity mismatch: input %.4f%%, output %.4f%%, raw passes %.4f%%\n", input,
              output, passthrough);

  // The passes were resolved, not copied: the diffuse colour differs from the raw samples.
  std::size_t changed = 0;
  for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
    changed += std::abs(out.at(p, "DiffCol.R") - in.at(p, "DiffCol.R")) > 1e-3f;
  }
  EXPECT_GT(changed, in.spec.image_pixels() / 50);

  // Normals averaged, then unit length again; the index is the frame's own sample, never a
  // blend of two objects' indices.
  for (std::size_t p = 0; p < out.spec.image_pixels(); ++p) {
    const float x = out.at(p, "Normal.X"), y = out.at(p, "Normal.Y"), z = out.at(p, "Normal.Z");
    ASSERT_NEAR(std::sqrt(x * x + y * y + z * z), 1.0f, 1e-4f) << "pixel " << p;
    ASSERT_EQ(out.at(p, "IndexOB.X"), in.at(p, "IndexOB.X")) << "pixel " << p;
  }
}

// The passes are weighed as the beauty's own stratified, two-cluster mean weighs their samples
// (window_gather.frag's shares): the beauty of a run with every pass is the beauty of a run
// without them, bit for bit, and a light pass that is a tenth of the beauty in every sample
// (Emit) is a tenth of it resolved (without the reconstruction's taps, which the beauty clamps
// to its samples' range and a pass cannot). (Before, a run with passes took the plain mean for
// the beauty and the passes alike: they agreed, but the beauty had lost its strata and
// clusters.)
TEST_F(PassesTest, EveryPassKeepsTheBeautyAloneAndFollowsIt) {
  auto resolve = [&](const std::string& out, std::vector<std::string> extra) {
    extra.insert(extra.end(), {"--window-reconstruction-weight", "0"});
    const ToolRun r = run(extra, out);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readExr(dir_ / out / frameName("r", 3));
  };
  const Exr withPasses = resolve("with-passes", {});
  const Exr colourAlone = resolve("colour-alone", {"--aov", "*=drop"});
  const Exr plain =
      resolve("plain", {"--window-strata", "off", "--window-two-clusters", "off"});
  std::size_t stratified = 0;
  for (std::size_t p = 0; p < withPasses.spec.image_pixels(); ++p) {
    for (const std::string& c : kRgb) {
      const float beauty = withPasses.at(p, c);
      ASSERT_EQ(beauty, colourAlone.at(p, c)) << "pixel " << p << " " << c;
      // Both half: within their rounding (a 2^-11 relative step each).
      ASSERT_NEAR(withPasses.at(p, "Emit." + c), 0.1f * beauty, 2e-3f * std::abs(beauty) + 1e-6f)
          << "pixel " << p << " " << c;
      ASSERT_NEAR(plain.at(p, "Emit." + c), 0.1f * plain.at(p, c),
                  2e-3f * std::abs(plain.at(p, c)) + 1e-6f)
          << "pixel " << p << " " << c;
    }
    stratified += std::abs(withPasses.at(p, "R") - plain.at(p, "R")) > 2e-3f;
  }
  // The strata were in effect (this scene's edges are a moving object's, where two clusters
  // do not apply: WindowTest.PassesFollowTheBarsTwoClusters checks those): the edges' pixels
  // differ from the plain mean's.
  EXPECT_GT(stratified, 20u);
  std::printf("every pass: %zu pixels of the beauty differ from the plain mean's\n", stratified);
}

// A pixel's (ID, coverage) pairs over the two rank layers, in rank order.
std::vector<std::pair<float, float>> rankPairsOf(const Exr& exr, std::size_t p) {
  std::vector<std::pair<float, float>> pairs;
  for (const char* layer : {"CryptoObject00.", "CryptoObject01."}) {
    for (const char* pair : {"rg", "ba"}) {
      pairs.emplace_back(exr.at(p, layer + std::string(1, pair[0])),
                         exr.at(p, layer + std::string(1, pair[1])));
    }
  }
  return pairs;
}

// The coverage of `id` over a pixel's rank pairs: how a comp pulls a matte.
float matteOf(const Exr& exr, std::size_t p, float id) {
  float coverage = 0.0f;
  for (const auto& [rankId, rankCoverage] : rankPairsOf(exr, p)) {
    if (rankId == id) coverage += rankCoverage;
  }
  return coverage;
}

// Cryptomatte: each ID's coverage is the weighted share of the samples that carry it, weighed
// as the beauty weighs them: the same as a light pass of the same matte (the reconstruction's
// taps, which a coverage cannot take, are left out of both), ranks heaviest first, the
// metadata kept, edges anti-aliased where the input's are hard.
TEST_F(PassesTest, CryptomatteCoverageIsTheWeightedShareOfTheSamples) {
  const ToolRun r = run({"--window-reconstruction-weight", "0"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const int f = 3;
  const Exr in = readExr(in_ / frameName("beauty", f));
  const Exr out = readExr(dir_ / "out" / frameName("r", f));
  EXPECT_EQ(out.spec.get_string_attribute("cryptomatte/f834d0a/name"), "CryptoObject");
  std::size_t softIn = 0, softOut = 0;
  for (std::size_t p = 0; p < out.spec.image_pixels(); ++p) {
    float total = 0.0f, previous = 2.0f;
    for (const auto& [id, coverage] : rankPairsOf(out, p)) {
      ASSERT_LE(coverage, previous) << "pixel " << p << ": ranks not heaviest first";
      previous = coverage;
      total += coverage;
      if (coverage > 0.0f) {
        ASSERT_TRUE(id == kIdRed || id == kIdOther) << "pixel " << p;
      }
    }
    ASSERT_NEAR(total, 1.0f, 1e-4f) << "pixel " << p;
    const float matte = matteOf(out, p, kIdRed);
    ASSERT_NEAR(matte, out.at(p, "MatteRed.R"), 2e-3f) << "pixel " << p;
    softOut += matte > 0.05f && matte < 0.95f;
    softIn += matteOf(in, p, kIdRed) > 0.05f && matteOf(in, p, kIdRed) < 0.95f;
  }
  EXPECT_EQ(softIn, 0u);
  EXPECT_GT(softOut, 20u);
  std::printf("Cryptomatte: %zu pixels of the red object's matte between 0.05 and 0.95\n",
              softOut);
}

// Cryptomatte beside the colour alone (no other pass): the beauty is the stratified mean of
// its own draw (--window-strata), as without the mattes, and the mattes weigh each sample as
// that mean does. The colour is made the red object's matte itself (1 on it, 0 off it), so the
// resolved colour and the matte pulled from the resolved Cryptomatte must agree pixel for
// pixel. (Before, the Cryptomatte draw wrote the plain mean over the beauty: the mattes agreed
// with a colour that had silently lost its strata.)
TEST_F(PassesTest, CryptomatteAloneKeepsTheStratifiedBeautyAndFollowsIt) {
  const fs::path only = dir_ / "cryptomatte-only";
  fs::create_directories(only);
  for (int f = 1; f <= kFrames; ++f) {
    const Exr in = readExr(in_ / frameName("beauty", f));
    std::vector<std::string> names = {"R", "G", "B", "A"};
    for (const char* layer : {"CryptoObject00.", "CryptoObject01."}) {
      for (const char* c : {"r", "g", "b", "a"}) names.push_back(layer + std::string(c));
    }
    OIIO::ImageSpec spec(kWidth, kHeight, int(names.size()), OIIO::TypeHalf);
    spec.channelnames = names;
    spec.alpha_channel = 3;
    spec.channelformats.assign(4, OIIO::TypeHalf);
    spec.channelformats.resize(names.size(), OIIO::TypeFloat);
    spec.attribute("cryptomatte/f834d0a/name", "CryptoObject");
    std::vector<float> pixels;
    for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
      const float red = in.at(p, "CryptoObject00.r") == kIdRed ? 1.0f : 0.0f;
      for (float v : {red, red, red, 1.0f}) pixels.push_back(v);
      for (const char* c : {"r", "g", "b", "a"}) {
        pixels.push_back(in.at(p, "CryptoObject00." + std::string(c)));
      }
      for (int c = 0; c < 4; ++c) pixels.push_back(0.0f);
    }
    writeFrameInto(only, f, spec, pixels);
  }
  auto resolve = [&](const std::string& out, std::vector<std::string> extra) {
    std::vector<std::string> args = test::separateFileArgs(only, dir_ / out / "r.####.exr");
    args.insert(args.end(), {"--window-reconstruction-weight", "0"});
    args.insert(args.end(), extra.begin(), extra.end());
    const ToolRun r = test::runTaatool(args, dir_);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return readExr(dir_ / out / frameName("r", 3));
  };
  const Exr withMattes = resolve("with-mattes", {});
  const Exr colourAlone = resolve("colour-alone", {"--aov", "*=drop"});
  const Exr plain = resolve("plain", {"--window-strata", "off"});
  std::size_t stratified = 0;
  for (std::size_t p = 0; p < withMattes.spec.image_pixels(); ++p) {
    ASSERT_EQ(withMattes.at(p, "R"), colourAlone.at(p, "R")) << "pixel " << p;
    // Half output: within its rounding of values up to 1.
    ASSERT_NEAR(matteOf(withMattes, p, kIdRed), withMattes.at(p, "R"), 1e-3f) << "pixel " << p;
    stratified += std::abs(withMattes.at(p, "R") - plain.at(p, "R")) > 2e-3f;
  }
  // The strata were in effect: the edges' pixels differ from the plain mean's.
  EXPECT_GT(stratified, 20u);
  std::printf("Cryptomatte alone: %zu pixels of the stratified colour differ from the plain\n",
              stratified);
}

// More IDs around a pixel than it keeps slots for (eight): twelve IDs laid so that every
// pixel's samples over the window carry most of them. A pixel keeps the heaviest it met; an ID
// that had to take a lighter one's slot starts again from its sample, so a kept ID's coverage
// is never more than its true share: the light pass of its matte, weighed as the beauty weighs
// it. The ranks stay heaviest first and their sum at most 1 (dropped IDs still count). (Checked
// to fail when a slot taken over keeps its old weight, and with five slots.)
TEST_F(PassesTest, CryptomatteWithMoreIdsThanSlotsKeepsTheHeaviestAndNeverOvercounts) {
  constexpr int kIds = 12;
  const auto idOf = [](int index) { return 0.25f + float(index); };
  const fs::path many = dir_ / "many-ids";
  fs::create_directories(many);
  for (int f = 1; f <= kFrames; ++f) {
    const Exr in = readExr(in_ / frameName("beauty", f));
    std::vector<std::string> names = {"R", "G", "B", "A"};
    for (int i = 0; i < kIds; ++i) names.push_back("Matte" + std::to_string(i) + ".R");
    for (const char* layer : {"CryptoObject00.", "CryptoObject01."}) {
      for (const char* c : {"r", "g", "b", "a"}) names.push_back(layer + std::string(c));
    }
    OIIO::ImageSpec spec(kWidth, kHeight, int(names.size()), OIIO::TypeFloat);
    spec.channelnames = names;
    spec.alpha_channel = 3;
    spec.attribute("cryptomatte/f834d0a/name", "CryptoObject");
    std::vector<float> pixels;
    for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
      const int x = int(p % kWidth), y = int(p / kWidth);
      const int id = (x + 2 * y + 3 * f) % kIds;
      for (const char* c : {"R", "G", "B", "A"}) pixels.push_back(in.at(p, c));
      for (int i = 0; i < kIds; ++i) pixels.push_back(i == id ? 1.0f : 0.0f);
      for (float v : {idOf(id), 1.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f, 0.0f}) pixels.push_back(v);
    }
    writeFrameInto(many, f, spec, pixels);
  }
  std::vector<std::string> args = test::separateFileArgs(many, dir_ / "many-out" / "r.####.exr");
  args.insert(args.end(), {"--window-reconstruction-weight", "0"});
  const ToolRun r = test::runTaatool(args, dir_);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Exr out = readExr(dir_ / "many-out" / frameName("r", 3));
  std::size_t full = 0, topExact = 0, crowded = 0;
  for (std::size_t p = 0; p < out.spec.image_pixels(); ++p) {
    float total = 0.0f, previous = 2.0f;
    int ranks = 0;
    for (const auto& [id, coverage] : rankPairsOf(out, p)) {
      ASSERT_LE(coverage, previous) << "pixel " << p << ": ranks not heaviest first";
      previous = coverage;
      total += coverage;
      if (coverage <= 0.0f) continue;
      const int index = int(id);
      ASSERT_EQ(id, idOf(index)) << "pixel " << p << ": an ID the input does not hold";
      ASSERT_TRUE(index >= 0 && index < kIds) << "pixel " << p;
      const float matte = out.at(p, "Matte" + std::to_string(index) + ".R");
      ASSERT_LE(coverage, matte + 1e-4f) << "pixel " << p << ", ID " << index;
      topExact += ranks == 0 && std::abs(coverage - matte) <= 1e-4f;
      ++ranks;
    }
    ASSERT_LE(total, 1.0f + 1e-4f) << "pixel " << p;
    full += ranks == 4;
    // The IDs the pixel met, by their mattes.
    int met = 0;
    for (int i = 0; i < kIds; ++i) met += out.at(p, "Matte" + std::to_string(i) + ".R") > 0.0f;
    crowded += met > 8;
  }
  const std::size_t pixels = out.spec.image_pixels();
  // Pixels met more IDs than their slots, and fill the two rank layers.
  EXPECT_GT(crowded, pixels / 2);
  EXPECT_EQ(full, pixels);
  // The heaviest ID keeps its whole share nearly everywhere.
  EXPECT_GT(topExact, pixels * 9 / 10);
  std::printf("Cryptomatte, %d IDs: more than 8 met in %zu of %zu pixels, the heaviest exact in "
              "%zu\n", kIds, crowded, pixels, topExact);
}

// The gather writes its pass sums as images where the context has image stores (one draw for
// every group and the first Cryptomatte set, in bands of 128 rows) and as draw buffers
// otherwise (six groups a draw, a draw a Cryptomatte set; TAA_GL_IMAGE_STORES=0 chooses them):
// the same files bit for bit. Eleven groups and two Cryptomatte sets, so that the draw buffers
// take two group draws and two Cryptomatte draws; 200 rows, a whole band and part of one. And
// the groups' rings (resolve/pass_packs) change no bit: side by side in rings of three
// (TAA_PASS_PACK_GROUPS=3: several rings of each type, some read by both draws of the draw
// buffers), as the driver takes them, or a ring a group.
TEST_F(PassesTest, ImageStoresAndDrawBuffersWriteThePassesAlike) {
  constexpr float kIdMaterial = 3.25e-5f;
  constexpr int kTallFrames = 3;
  in_ = dir_ / "tall";
  test::writeSeparateFrames(in_, 1, kTallFrames, 24, 200);
  for (int f = 1; f <= kTallFrames; ++f) {
    const fs::path path = in_ / frameName("beauty", f);
    addPasses(path);
    const Exr in = readExr(path);
    OIIO::ImageSpec spec = in.spec;
    std::vector<float> pixels;
    const int extraLights = 8;
    for (int l = 0; l < extraLights; ++l) {
      for (const std::string& c : kRgb) {
        spec.channelnames.push_back("Light" + std::to_string(l) + "." + c);
        spec.channelformats.push_back(OIIO::TypeHalf);
      }
    }
    for (const char* c : {"r", "g", "b", "a"}) {
      spec.channelnames.push_back("CryptoMaterial00." + std::string(c));
      spec.channelformats.push_back(OIIO::TypeFloat);
    }
    spec.nchannels = int(spec.channelnames.size());
    spec.attribute("cryptomatte/a1b2c3d/name", "CryptoMaterial");
    for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
      const float* own = &in.pixels[p * std::size_t(in.spec.nchannels)];
      pixels.insert(pixels.end(), own, own + in.spec.nchannels);
      for (int l = 0; l < extraLights; ++l) {
        for (const std::string& c : kRgb) pixels.push_back(0.1f * (l + 1) * in.at(p, c));
      }
      const bool red = in.at(p, "CryptoObject00.r") == kIdRed;
      for (float v : {red ? kIdMaterial : kIdOther, 1.0f, 0.0f, 0.0f}) pixels.push_back(v);
    }
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
    ASSERT_TRUE(out->close());
  }
  // The draws each way, by TAA_GL_PROFILE's lines.
  setenv("TAA_GL_PROFILE", "1", 1);
  const ToolRun images = run({"-q"}, "images");
  setenv("TAA_GL_IMAGE_STORES", "0", 1);
  setenv("TAA_PASS_PACK_GROUPS", "3", 1);
  const ToolRun buffers = run({"-q"}, "buffers");
  unsetenv("TAA_GL_IMAGE_STORES");
  unsetenv("TAA_GL_PROFILE");
  const ToolRun packsOfThree = run({"-q"}, "packs-of-three");
  setenv("TAA_PASS_PACK_GROUPS", "1", 1);
  const ToolRun ringEach = run({"-q"}, "ring-each");
  unsetenv("TAA_PASS_PACK_GROUPS");
  ASSERT_EQ(images.exitCode, 0) << images.err;
  ASSERT_EQ(buffers.exitCode, 0) << buffers.err;
  ASSERT_EQ(packsOfThree.exitCode, 0) << packsOfThree.err;
  ASSERT_EQ(ringEach.exitCode, 0) << ringEach.err;
  const auto draws = [](const std::string& err, const std::string& pass) {
    const std::size_t at = err.find("\n" + pass + " ");
    return at == std::string::npos ? -1 : std::atoi(err.c_str() + at + pass.size() + 2);
  };
  const std::string joined = "window gather pass (pass groups and Cryptomatte)";
  const std::string groups = "window gather pass (pass groups)";
  const std::string cryptomatte = "window gather pass (Cryptomatte)";
  // Two bands a frame with image stores.
  EXPECT_EQ(draws(images.err, joined), 2 * kTallFrames) << images.err;
  EXPECT_EQ(draws(images.err, groups), -1) << images.err;
  EXPECT_EQ(draws(images.err, cryptomatte), 2 * kTallFrames) << images.err;  // the second set
  EXPECT_EQ(draws(buffers.err, joined), -1) << buffers.err;
  EXPECT_EQ(draws(buffers.err, groups), 2 * kTallFrames) << buffers.err;
  EXPECT_EQ(draws(buffers.err, cryptomatte), 2 * kTallFrames) << buffers.err;
  for (int f = 1; f <= kTallFrames; ++f) {
    const Exr a = readExr(dir_ / "images" / frameName("r", f));
    for (const char* other : {"buffers", "packs-of-three", "ring-each"}) {
      const Exr b = readExr(dir_ / other / frameName("r", f));
      ASSERT_EQ(a.spec.channelnames, b.spec.channelnames);
      ASSERT_EQ(a.pixels.size(), b.pixels.size());
      std::size_t differing = 0;
      for (std::size_t i = 0; i < a.pixels.size(); ++i) {
        differing += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
      }
      EXPECT_EQ(differing, 0u) << other << ", frame " << f;
    }
  }
}

// The passes go to the writer band by band as the GL draws them, the frame's write running
// beside the pass draws: every channel the same as with the whole frame's sums written after the
// draws (--threads 0), and a write that fails ends the run with its error rather than leaving
// the GL waiting for it to take the next band.
TEST_F(PassesTest, PassesStreamedToTheWriterAreTheWholeFramesAndAFailedWriteEndsTheRun) {
  constexpr int kTallFrames = 3;  // 200 rows: two bands of the pass draws
  in_ = dir_ / "tall";
  test::writeSeparateFrames(in_, 1, kTallFrames, 24, 200);
  for (int f = 1; f <= kTallFrames; ++f) addPasses(in_ / frameName("beauty", f));
  const ToolRun streamed = run({"-v"}, "streamed");
  const ToolRun whole = run({"-v", "--threads", "0"}, "whole");
  ASSERT_EQ(streamed.exitCode, 0) << streamed.err;
  ASSERT_EQ(whole.exitCode, 0) << whole.err;
  const std::string told = "the passes go to the writer band by band";
  EXPECT_NE(streamed.err.find(told), std::string::npos) << streamed.err;
  EXPECT_EQ(whole.err.find(told), std::string::npos) << whole.err;
  for (int f = 1; f <= kTallFrames; ++f) {
    const Exr a = readExr(dir_ / "streamed" / frameName("r", f));
    const Exr b = readExr(dir_ / "whole" / frameName("r", f));
    ASSERT_EQ(a.spec.channelnames, b.spec.channelnames);
    ASSERT_GT(a.spec.nchannels, 20);
    ASSERT_EQ(a.pixels.size(), b.pixels.size());
    std::size_t differing = 0;
    for (std::size_t i = 0; i < a.pixels.size(); ++i) {
      differing += std::memcmp(&a.pixels[i], &b.pixels[i], sizeof(float)) != 0;
    }
    EXPECT_EQ(differing, 0u) << "frame " << f;
  }
  // Frame 2's output path taken by a folder: its write fails once its bands have come.
  fs::create_directories(dir_ / "failing" / frameName("r", 2));
  const ToolRun failed = run({"-v"}, "failing");
  EXPECT_NE(failed.exitCode, 0) << failed.err;
  EXPECT_NE(failed.err.find(frameName("r", 2)), std::string::npos) << failed.err;
  EXPECT_TRUE(fs::exists(dir_ / "failing" / frameName("r", 1)));
}

// A float data pass keeps values a half colour output cannot hold: the colour's 65504 limit is
// the colour's alone (the pass was once clamped to it).
TEST_F(PassesTest, FloatPassesKeepValuesBeyondHalfsRange) {
  constexpr float kScale = 1e6f;
  for (int f = 1; f <= kFrames; ++f) {
    const fs::path path = in_ / frameName("beauty", f);
    Exr exr = readExr(path);
    const std::size_t matte = std::size_t(exr.spec.channelindex("MatteRed.R"));
    for (std::size_t p = 0; p < exr.spec.image_pixels(); ++p) {
      exr.pixels[p * std::size_t(exr.spec.nchannels) + matte] *= kScale;
    }
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), exr.spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, exr.pixels.data()));
    ASSERT_TRUE(out->close());
  }
  const ToolRun r = run({"--aov", "MatteRed.*=average"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const Exr out = readExr(dir_ / "out" / frameName("r", 3));
  ASSERT_EQ(out.spec.channelformat(out.spec.channelindex("R")), OIIO::TypeHalf);
  ASSERT_EQ(out.spec.channelformat(out.spec.channelindex("MatteRed.R")), OIIO::TypeFloat);
  // Finite, within the input's range and the reconstruction's ringing, and not cut at 65504.
  float largest = 0.0f;
  for (std::size_t p = 0; p < out.spec.image_pixels(); ++p) {
    const float v = out.at(p, "MatteRed.R");
    ASSERT_TRUE(std::isfinite(v) && std::abs(v) <= 1.01f * kScale) << "pixel " << p << ": " << v;
    largest = std::max(largest, v);
  }
  EXPECT_GT(largest, 0.99f * kScale);
}

TEST_F(PassesTest, AovRulesChooseKindsAndDropChannels) {
  // Everything but the colour dropped: the colour alone, as before passes were resolved.
  ToolRun r = run({"--aov", "*=drop"}, "dropped");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  Exr out = readExr(dir_ / "dropped" / frameName("r", 3));
  EXPECT_EQ(out.spec.channelnames, (std::vector<std::string>{"R", "G", "B", "A"}));

  // A rule wins over the pass name: the diffuse colour copied untouched, the rest dropped.
  r = run({"--aov", "DiffCol.*=copy", "--aov", "*=drop"}, "copied");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  out = readExr(dir_ / "copied" / frameName("r", 3));
  const Exr in = readExr(in_ / frameName("beauty", 3));
  EXPECT_EQ(out.spec.nchannels, 7);  // R, G, B, A and DiffCol's three
  for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
    ASSERT_EQ(out.at(p, "DiffCol.G"), in.at(p, "DiffCol.G")) << "pixel " << p;
  }

  // --passthrough keeps its meaning: untouched.
  r = run({"--passthrough", "Emit.*"}, "passthrough");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  out = readExr(dir_ / "passthrough" / frameName("r", 3));
  for (std::size_t p = 0; p < in.spec.image_pixels(); ++p) {
    ASSERT_EQ(out.at(p, "Emit.B"), in.at(p, "Emit.B")) << "pixel " << p;
  }
}

TEST_F(PassesTest, BadRulesAndTheHistoryModeAreRefusedWithAMessage) {
  test::expectToolError(run({"--aov", "DiffCol.*=albedo"}),
                        {"--aov 'DiffCol.*=albedo': unknown kind 'albedo'", "light, factor"});
  test::expectToolError(run({"--aov", "DiffCol.*"}), {"--aov wants PATTERN=kind"});
  test::expectToolError(run({"--mode", "history", "--aov", "*=light"}), {"--mode window"});
  // The history mode without --aov writes the colour alone, as it always did.
  const ToolRun r = run({"--mode", "history"}, "history");
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(readExr(dir_ / "history" / frameName("r", 3)).spec.nchannels, 4);
}

// The C ABI node (taa.h) resolves a render's passes as taatool does: the same frames pushed with
// their passes (light passes in half buffers, data in float ones, as the file holds them) give
// taatool's channels bit for bit, and a pass the node was not given is an error naming the ones
// it has.
TEST_F(PassesTest, TheCApiNodeResolvesThePassesAsTaatoolDoes) {
  const ToolRun r = run({});
  ASSERT_EQ(r.exitCode, 0) << r.err;

  // Every frame as the host holds it: the beauty file's channels as float and as half.
  struct HostFrame {
    Exr beauty, depth, motion;
    std::vector<Imath::half> halves;
    taa_buffer floats{}, halfs{}, color{}, depthBuffer{}, motionBuffer{};
    std::vector<taa_pass> passes;
    std::vector<float> toCamera, toNdc;
  };
  std::vector<HostFrame> frames(kFrames);
  for (int f = 1; f <= kFrames; ++f) {
    HostFrame& h = frames[std::size_t(f - 1)];
    h.beauty = readExr(in_ / frameName("beauty", f));
    h.depth = readExr(in_ / frameName("depth", f));
    h.motion = readExr(in_ / frameName("motion", f));
    const OIIO::ImageSpec& spec = h.beauty.spec;
    h.halves.assign(h.beauty.pixels.begin(), h.beauty.pixels.end());
    const auto buffer = [&](void* data, int channels, taa_pixel_type type) {
      taa_buffer b{};
      b.data = data;
      b.width = kWidth;
      b.height = kHeight;
      b.channels = channels;
      b.type = type;
      return b;
    };
    h.floats = buffer(h.beauty.pixels.data(), spec.nchannels, TAA_PIXEL_FLOAT);
    h.halfs = buffer(h.halves.data(), spec.nchannels, TAA_PIXEL_HALF);
    ASSERT_EQ(spec.channelindex("R"), 0);
    ASSERT_EQ(spec.channelindex("A"), 3);
    h.color = h.floats;
    h.color.channels = 4;
    h.color.pixel_stride_bytes = std::ptrdiff_t(spec.nchannels) * 4;
    h.depthBuffer = buffer(h.depth.pixels.data(), 1, TAA_PIXEL_FLOAT);
    h.motionBuffer = buffer(h.motion.pixels.data(), 2, TAA_PIXEL_FLOAT);
    for (int c = 4; c < spec.nchannels; ++c) {
      const bool half = spec.channelformat(c) == OIIO::TypeHalf;
      h.passes.push_back({spec.channelnames[std::size_t(c)].c_str(), half ? &h.halfs : &h.floats,
                          c});
    }
    for (const auto& [name, to] : {std::pair{"worldToCamera", &h.toCamera},
                                   std::pair{"worldToNDC", &h.toNdc}}) {
      if (const OIIO::ParamValue* m = spec.find_attribute(name, OIIO::TypeMatrix44)) {
        const auto* v = static_cast<const float*>(m->data());
        to->assign(v, v + 16);
      }
    }
  }

  taa_node* node = nullptr;
  ASSERT_EQ(taa_node_create(nullptr, &node), TAA_OK) << taa_last_error();
  ASSERT_EQ(taa_node_set_string(node, "mode", "window"), TAA_OK) << taa_node_last_error(node);
  // Frame f as the host pushes it: colour, depth, motion and the header's camera.
  const auto frameOf = [&frames](int f) {
    HostFrame& h = frames[std::size_t(f - 1)];
    taa_frame frame;
    taa_frame_init(&frame);
    frame.frame = f;
    frame.color = &h.color;
    frame.depth = &h.depthBuffer;
    frame.motion = &h.motionBuffer;
    if (!h.toCamera.empty() && !h.toNdc.empty()) {
      frame.world_to_camera = h.toCamera.data();
      frame.world_to_ndc = h.toNdc.data();
    }
    return frame;
  };
  for (int f = 1; f <= kFrames; ++f) {
    const HostFrame& h = frames[std::size_t(f - 1)];
    const taa_frame frame = frameOf(f);
    ASSERT_EQ(taa_node_push_frame_passes(node, &frame, h.passes.data(), int(h.passes.size())),
              TAA_OK)
        << taa_node_last_error(node);
  }

  const int f = 3;
  ASSERT_EQ(taa_node_resolve_frame(node, f), TAA_OK) << taa_node_last_error(node);
  const Exr out = readExr(dir_ / "out" / frameName("r", f));
  const HostFrame& h = frames[std::size_t(f - 1)];
  // Read back as the file holds them: half channels into a half buffer, the rest as float.
  std::vector<float> floats(h.beauty.pixels.size());
  std::vector<Imath::half> halves(h.beauty.pixels.size());
  taa_buffer floatOut = h.floats, halfOut = h.halfs;
  floatOut.data = floats.data();
  halfOut.data = halves.data();
  std::vector<taa_pass> wanted = h.passes;
  for (taa_pass& pass : wanted) pass.buffer = pass.buffer == &h.halfs ? &halfOut : &floatOut;
  ASSERT_EQ(taa_node_read_passes(node, wanted.data(), int(wanted.size())), TAA_OK)
      << taa_node_last_error(node);
  for (const taa_pass& pass : wanted) {
    const bool half = pass.buffer == &halfOut;
    for (std::size_t p = 0; p < out.spec.image_pixels(); ++p) {
      const std::size_t at = p * std::size_t(h.beauty.spec.nchannels) + std::size_t(pass.channel);
      const float fromNode = half ? float(halves[at]) : floats[at];
      const float tool = out.at(p, pass.name);
      // The same GPU program on the same values in the same types: taatool's value bit for bit.
      ASSERT_EQ(fromNode, tool) << pass.name << ", pixel " << p;
    }
  }

  // Frame 3 pushed again without passes: the frames pushed with them leave the ring, and a
  // window that needs one says so.
  const taa_frame again = frameOf(f);
  ASSERT_EQ(taa_node_push_frame(node, &again), TAA_OK) << taa_node_last_error(node);
  EXPECT_EQ(taa_node_resolve_frame(node, f), TAA_ERROR_MISSING_FRAME);
  EXPECT_NE(std::string(taa_node_last_error(node)).find("pushed with other passes"),
            std::string::npos)
      << taa_node_last_error(node);

  // The "aov" parameter takes taatool's rules separated by ';' and names itself when one is bad.
  EXPECT_EQ(taa_node_set_string(node, "aov", "Emit.*=copy;;*=drop"), TAA_OK)
      << taa_node_last_error(node);
  EXPECT_EQ(taa_node_set_string(node, "aov", "Emit.*=copy;Emit.*=albedo"),
            TAA_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(taa_node_last_error(node)).find("parameter \"aov\": "),
            std::string::npos)
      << taa_node_last_error(node);
  EXPECT_NE(std::string(taa_node_last_error(node)).find("albedo"), std::string::npos)
      << taa_node_last_error(node);

  // A pass it was not given; passes in history mode.
  taa_pass unknown{"Shadow.R", &floatOut, 0};
  EXPECT_EQ(taa_node_read_passes(node, &unknown, 1), TAA_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(taa_node_last_error(node)).find("no pass \"Shadow.R\" (it has CryptoObject00.r, CryptoObject00.g"),
            std::string::npos)
      << taa_node_last_error(node);
  ASSERT_EQ(taa_node_set_string(node, "mode", "history"), TAA_OK);
  taa_frame frame;
  taa_frame_init(&frame);
  frame.frame = 1;
  frame.color = &frames[0].color;
  EXPECT_EQ(taa_node_push_frame_passes(node, &frame, frames[0].passes.data(),
                                       int(frames[0].passes.size())),
            TAA_ERROR_INVALID_ARGUMENT);
  EXPECT_NE(std::string(taa_node_last_error(node)).find("\"mode\" = \"window\""),
            std::string::npos)
      << taa_node_last_error(node);
  taa_node_destroy(node);
}

}  // namespace
}  // namespace taa
