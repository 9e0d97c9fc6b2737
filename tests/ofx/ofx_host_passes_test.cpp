// The Pass clip (issue 21): another pass of the render resolved with the Source's weights. Each
// kind's output is taatool's resolve of the same pass in a multi-channel file beside the same
// beauty, bit for bit: a light pass with its colour (Pass Factor) and the colour pass itself,
// an object index (nearest: the frame's own value) and a Cryptomatte rank layer.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <cstdlib>

#include "ofx_host_fixture.h"
#include "taatool_runner.h"

namespace taa::ofxtest {
namespace {

namespace fs = std::filesystem;

constexpr float kIdRed = 3.5e-5f, kIdOther = -2.25e12f;  // two Cryptomatte ID hashes

std::string frameName(int frame) { return std::to_string(10000 + frame).substr(1); }

// A sample's passes, made from its colour: a colour (albedo) that varies with it, the light
// that colour reflects (60 % of the beauty), an object index and its Cryptomatte ID.
float diffuseColour(const float* rgb) {
  return 0.25f + 0.5f * (0.5f + 0.5f * std::sin(13.0f * (rgb[0] + 2.0f * rgb[1])));
}

class OfxHostPassesTest : public OfxHostTest {
 protected:
  static void SetUpTestSuite() {
    OfxHostTest::SetUpTestSuite();
    light_ = colour_ = index_ = crypto_ = ClipFrames{};
    for (int f = kFirst; f <= kLast; ++f) {
      const Image& beauty = colorFrame(f);
      Image light(beauty.width, beauty.height, 3), colour = light;
      Image index(beauty.width, beauty.height, 1), crypto(beauty.width, beauty.height, 4);
      for (std::size_t p = 0; p < std::size_t(beauty.width) * beauty.height; ++p) {
        const float* rgb = &beauty.pixels[4 * p];
        const bool red = rgb[0] > rgb[1];
        for (int c = 0; c < 3; ++c) {
          colour.pixels[3 * p + c] = diffuseColour(rgb);
          light.pixels[3 * p + c] = 0.6f * rgb[c] / diffuseColour(rgb);
        }
        index.pixels[p] = red ? 2.0f : 1.0f;
        const float pairs[4] = {red ? kIdRed : kIdOther, 1.0f, 0.0f, 0.0f};
        for (int c = 0; c < 4; ++c) crypto.pixels[4 * p + c] = pairs[c];
      }
      light_.frames[f] = light;
      colour_.frames[f] = colour;
      index_.frames[f] = index;
      crypto_.frames[f] = crypto;
      writePassFile(f);
    }
    // Every pass, and (into out-cryptomatte) Cryptomatte alone: an effect resolves one pass
    // beside the Source, and Cryptomatte without light passes follows the stratified colour.
    const fs::path in = dir_ / "passes";
    const std::vector<std::string> window = {"--mode", "window", "--window", "2"};
    runTaatool(in / "beauty.####.exr", in / "out", window);
    std::vector<std::string> cryptomatteAlone = window;
    cryptomatteAlone.insert(cryptomatteAlone.end(),
                            {"--aov", "Crypto*=cryptomatte", "--aov", "*=drop"});
    runTaatool(in / "beauty.####.exr", in / "out-cryptomatte", cryptomatteAlone);
  }

  // The fixture's beauty file (its header kept) with the passes as channels named as Cycles
  // names them, float, so taatool resolves them by their default kinds.
  static void writePassFile(int f) {
    const std::string name = "beauty." + frameName(f) + ".exr";
    auto in = OIIO::ImageInput::open((dir_ / name).string());
    ASSERT_TRUE(in);
    OIIO::ImageSpec spec = in->spec();
    std::vector<float> beauty(spec.image_pixels() * std::size_t(spec.nchannels));
    ASSERT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, beauty.data()));
    const int first = spec.nchannels;
    spec.channelnames.resize(std::size_t(first));
    for (const char* c : {"DiffDir.R", "DiffDir.G", "DiffDir.B", "DiffCol.R", "DiffCol.G",
                          "DiffCol.B", "IndexOB.X", "CryptoObject00.r", "CryptoObject00.g",
                          "CryptoObject00.b", "CryptoObject00.a"}) {
      spec.channelnames.push_back(c);
    }
    spec.nchannels = int(spec.channelnames.size());
    spec.set_format(OIIO::TypeFloat);
    spec.channelformats.clear();
    spec.attribute("cryptomatte/f834d0a/name", "CryptoObject");
    std::vector<float> pixels;
    // Rows top first in the file, the clips' images rows top first too (the host flips them).
    for (std::size_t p = 0; p < spec.image_pixels(); ++p) {
      for (int c = 0; c < first; ++c) pixels.push_back(beauty[p * std::size_t(first) + c]);
      for (int c = 0; c < 3; ++c) pixels.push_back(light_.frames[f].pixels[3 * p + c]);
      for (int c = 0; c < 3; ++c) pixels.push_back(colour_.frames[f].pixels[3 * p + c]);
      pixels.push_back(index_.frames[f].pixels[p]);
      for (int c = 0; c < 4; ++c) pixels.push_back(crypto_.frames[f].pixels[4 * p + c]);
    }
    fs::create_directories(dir_ / "passes");
    const std::string path = (dir_ / "passes" / name).string();
    auto out = OIIO::ImageOutput::create(path);
    ASSERT_TRUE(out && out->open(path, spec));
    ASSERT_TRUE(out->write_image(OIIO::TypeFloat, pixels.data()));
    ASSERT_TRUE(out->close());
  }

  // taatool's resolved channels of frame f (rows top first), as RGBA with `alpha` where the
  // pass has fewer than four channels (one channel: in all four), from the taatool `run`.
  static Image taatoolPass(int f, const std::vector<std::string>& names, float alpha = 1.0f,
                           const std::string& run = "out") {
    const std::string path =
        (dir_ / "passes" / run / ("out." + frameName(f) + ".exr")).string();
    auto in = OIIO::ImageInput::open(path);
    EXPECT_TRUE(in) << path;
    if (!in) return {};
    const OIIO::ImageSpec& spec = in->spec();
    std::vector<float> all(spec.image_pixels() * std::size_t(spec.nchannels));
    EXPECT_TRUE(in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeFloat, all.data()));
    std::vector<int> sources;
    for (const std::string& name : names) {
      sources.push_back(spec.channelindex(name));
      EXPECT_GE(sources.back(), 0) << name << " in " << path;
      if (sources.back() < 0) return {};
    }
    Image image(spec.width, spec.height, 4);
    for (std::size_t p = 0; p < spec.image_pixels(); ++p) {
      for (std::size_t c = 0; c < 4; ++c) {
        const std::size_t k = names.size() == 1 ? 0 : c;
        image.pixels[4 * p + c] =
            k < names.size() ? all[p * std::size_t(spec.nchannels) + std::size_t(sources[k])]
                             : alpha;
      }
    }
    return image;
  }

  void setPassKind(HostEffect& effect, int kind) {
    effect.params.at("mode").intValue = 1;
    effect.params.at("window").intValue = 2;
    effect.params.at("passKind").intValue = kind;
    for (const char* name : {"mode", "window", "passKind"}) {
      EXPECT_EQ(host_.parameterChanged(effect, name), kOfxStatOK);
    }
  }

  static inline ClipFrames light_, colour_, index_, crypto_;
};

TEST_F(OfxHostPassesTest, ALightWithItsColourIsTaatoolsResolve) {
  auto effect = instance(false, kLast, {{"Pass", &light_}, {"PassFactor", &colour_}});
  setPassKind(*effect, 0);  // Light
  for (int f : {5, 1, 8}) {
    const Image expected = taatoolPass(f, {"DiffDir.R", "DiffDir.G", "DiffDir.B"});
    // The comparison can fail: the resolved light is not the frame's own.
    Image own = expected;
    for (std::size_t p = 0; p < own.pixels.size() / 4; ++p) {
      for (int c = 0; c < 3; ++c) own.pixels[4 * p + c] = light_.frames[f].pixels[3 * p + c];
    }
    EXPECT_GT(maxDifference(own, expected), 1e-3f) << "frame " << f;
    EXPECT_EQ(maxDifference(render(*effect, f), expected), 0.0f) << "frame " << f;
  }
  EXPECT_EQ(host_.persistentMessage(*effect), "");
  // Without its factor the light is summed alone: another result.
  destroy(effect);
  auto alone = instance(false, kLast, {{"Pass", &light_}});
  setPassKind(*alone, 0);
  EXPECT_GT(maxDifference(render(*alone, 5), taatoolPass(5, {"DiffDir.R", "DiffDir.G",
                                                             "DiffDir.B"})),
            1e-4f);
  destroy(alone);
}

TEST_F(OfxHostPassesTest, FactorNearestAndCryptomatteAreTaatoolsResolve) {
  auto factor = instance(false, kLast, {{"Pass", &colour_}});
  setPassKind(*factor, 1);
  EXPECT_EQ(maxDifference(render(*factor, 4), taatoolPass(4, {"DiffCol.R", "DiffCol.G",
                                                              "DiffCol.B"})),
            0.0f);
  destroy(factor);
  auto nearest = instance(false, kLast, {{"Pass", &index_}});
  setPassKind(*nearest, 4);
  EXPECT_EQ(maxDifference(render(*nearest, 4), taatoolPass(4, {"IndexOB.X"})), 0.0f);
  destroy(nearest);
  auto crypto = instance(false, kLast, {{"Pass", &crypto_}});
  setPassKind(*crypto, 5);
  const Image ranks = taatoolPass(4, {"CryptoObject00.r", "CryptoObject00.g",
                                      "CryptoObject00.b", "CryptoObject00.a"},
                                  1.0f, "out-cryptomatte");
  EXPECT_EQ(maxDifference(render(*crypto, 4), ranks), 0.0f);
  // Coverage is shared between the two IDs somewhere (the object's edge): a real re-weighing.
  bool shared = false;
  for (std::size_t p = 0; p < ranks.pixels.size() / 4; ++p) {
    shared = shared || (ranks.pixels[4 * p + 1] > 0.0f && ranks.pixels[4 * p + 1] < 1.0f);
  }
  EXPECT_TRUE(shared);
  destroy(crypto);
}

// The passes are weighed by the beauty's own stratified, two-cluster mean (window_gather.frag's
// shares), so a run with every pass has the beauty a run without passes has: the Source's own
// effect gives taatool's every-pass beauty bit for bit, and Window Strata and Window Two
// Clusters change both.
TEST_F(OfxHostPassesTest, TheBeautyWithEveryPassIsTheBeautyAlone) {
  auto source = instance(false, kLast, {});
  setPassKind(*source, 0);  // mode and window as the pass effects'; no Pass clip
  const Image beauty = taatoolPass(4, {"R", "G", "B", "A"});
  EXPECT_EQ(maxDifference(render(*source, 4), beauty), 0.0f);
  for (const char* name : {"windowStrata", "windowTwoClusters"}) {
    source->params.at(name).intValue = 0;
    EXPECT_EQ(host_.parameterChanged(*source, name), kOfxStatOK);
  }
  EXPECT_GT(maxDifference(render(*source, 4), beauty), 1e-4f);
  destroy(source);
}

TEST_F(OfxHostPassesTest, ThePassClipIsFetchedForTheWindowAndRefusedInHistoryMode) {
  auto effect = instance(false, kLast, {{"Pass", &light_}, {"PassFactor", &colour_}});
  setPassKind(*effect, 0);
  PropertySet in, out;
  in.set(kOfxPropTime, {5.0});
  ASSERT_EQ(host_.action(kOfxImageEffectActionGetFramesNeeded, effect.get(), &in, &out),
            kOfxStatOK);
  for (const char* clip : {"Pass", "PassFactor"}) {
    const std::string name = std::string(kOfxImageClipPropFrameRangePrefix) + clip;
    ASSERT_EQ(out.dimension(name), 2) << name;
    EXPECT_EQ(out.getDouble(name, 0), 3.0);
    EXPECT_EQ(out.getDouble(name, 1), 7.0);
  }
  const int fetched = effect->clips.at("Pass").imagesServed;
  render(*effect, 5);
  EXPECT_EQ(effect->clips.at("Pass").imagesServed - fetched, 5);
  EXPECT_EQ(effect->clips.at("PassFactor").imagesServed, 5);
  effect->params.at("mode").intValue = 0;
  EXPECT_EQ(host_.parameterChanged(*effect, "mode"), kOfxStatOK);
  render(*effect, 5, kOfxStatFailed);
  EXPECT_NE(host_.persistentMessage(*effect).find("set Mode to Window"), std::string::npos)
      << host_.persistentMessage(*effect);
  destroy(effect);
}

TEST_F(OfxHostPassesTest, CryptomatteAsHalfIsRefusedNamingTheClip) {
  ClipFrames half = crypto_;
  half.half = true;
  auto effect = instance(false, kLast, {{"Pass", &half}});
  setPassKind(*effect, 5);
  render(*effect, 4, kOfxStatFailed);
  const std::string message = host_.persistentMessage(*effect);
  EXPECT_NE(message.find("Pass clip at frame"), std::string::npos) << message;
  EXPECT_NE(message.find("four float channels"), std::string::npos) << message;
  destroy(effect);
}

}  // namespace
}  // namespace taa::ofxtest
