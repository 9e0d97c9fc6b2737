// Each resolve stage's defining behaviour on tiny synthetic inputs (real GL, llvmpipe here).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <functional>

#include "gl/context.h"
#include "resolve/camera.h"
#include "resolve/jitter.h"
#include "resolve/resolver.h"

namespace taa {
namespace {

constexpr int kWidth = 24, kHeight = 12;

Image filled(int channels, const std::function<std::vector<float>(int x, int y)>& value) {
  Image image(kWidth, kHeight, channels);
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const std::vector<float> v = value(x, y);
      std::copy(v.begin(), v.end(), image.at(x, y));
    }
  }
  return image;
}

Image grey(float v) { return filled(4, [v](int, int) { return std::vector<float>{v, v, v, 1}; }); }
Image constant(int channels, float v) {
  return filled(channels, [&](int, int) { return std::vector<float>(channels, v); });
}

// Options that make single stages observable: no bracket, centre reconstruction, no jitter, a
// fixed blend of 0.1 whatever the speed.
ResolveOptions plainOptions() {
  ResolveOptions o;
  o.reconstruction = Reconstruction::Centre;
  o.blend = 0.1f;
  o.velocityBlend = 0.0f;
  o.jitter.source = JitterSource::None;
  o.sampleCount = false;
  o.color.bracket = "none";
  return o;
}

class StagesTest : public ::testing::Test {
 protected:
  void SetUp() override { context_ = gl::Context::create(gl::Backend::Auto); }

  Image run(Resolver& resolver, const Image& color, const Image* depth = nullptr,
            const Image* motion = nullptr, glm::vec2 jitter = {0, 0},
            const FrameCamera* camera = nullptr) {
    ResolveInput input;
    input.color = &color;
    input.depth = depth;
    input.motion = motion;
    input.jitter = jitter;
    input.camera = camera;
    input.window = {0, 0, kWidth, kHeight};
    return resolver.resolve(input);
  }

  std::unique_ptr<gl::Context> context_;
};

TEST_F(StagesTest, DisoccludedRegionResetsToTheCurrentFrame) {
  ResolveOptions o = plainOptions();
  o.rectify = Rectify::None;  // only the depth test may reject
  Resolver resolver(*context_, o);
  resolver.setDebugOutput(true);
  const Image near = constant(1, 1.0f);
  run(resolver, grey(0.0f), &near);
  // The right half now shows a surface 5x further away: it was hidden in the previous frame.
  const Image revealed = filled(1, [](int x, int) { return std::vector<float>{x >= 12 ? 5.f : 1.f}; });
  const Image out = run(resolver, grey(1.0f), &revealed);
  EXPECT_FLOAT_EQ(out.at(18, 6)[0], 1.0f);   // reset: current frame only
  EXPECT_FLOAT_EQ(out.at(18, 6)[3], 1.0f);
  EXPECT_NEAR(out.at(4, 6)[0], 0.1f, 1e-6f); // kept: blended with weight 0.1
  EXPECT_EQ(resolver.lastDebug().at(18, 6)[1], float(Rejection::Disoccluded));
  EXPECT_EQ(resolver.lastDebug().at(4, 6)[1], float(Rejection::Kept));
}

TEST_F(StagesTest, ThinOccluderInThePreviousFrameDoesNotRejectTheBackdrop) {
  // Last frame's centre samples hit a one-pixel wire at x = 8 that this frame's samples miss: the
  // backdrop around it was not hidden (only the wire's own footprint is nearer), so history stays.
  ResolveOptions o = plainOptions();
  o.rectify = Rectify::None;
  Resolver resolver(*context_, o);
  resolver.setDebugOutput(true);
  const Image wire = filled(1, [](int x, int) { return std::vector<float>{x == 8 ? 1.f : 5.f}; });
  run(resolver, grey(0.0f), &wire);
  const Image backdrop = constant(1, 5.0f);
  run(resolver, grey(1.0f), &backdrop);
  for (int x = 6; x <= 10; ++x) {
    EXPECT_EQ(resolver.lastDebug().at(x, 6)[1], float(Rejection::Kept)) << "x " << x;
  }
}

// Motion comes from the closest-depth pixel of the 3x3 (read by four gathers): each of the nine
// places, at the image's corners and edges too, where clamping repeats the border pixels.
TEST_F(StagesTest, MotionComesFromTheClosestDepthOfTheNeighbourhood) {
  Resolver resolver(*context_, plainOptions());
  resolver.setDebugOutput(true);
  // Every pixel's own motion, distinct, small enough to stay on screen.
  const Image motion = filled(2, [](int x, int y) {
    return std::vector<float>{0.01f * float(x), 0.01f * float(y) + 0.005f};
  });
  const glm::ivec2 last(kWidth - 1, kHeight - 1);
  for (const glm::ivec2 p : {glm::ivec2(5, 6), glm::ivec2(0, 0), last, glm::ivec2(last.x, 0),
                             glm::ivec2(10, last.y)}) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const glm::ivec2 near = glm::clamp(p + glm::ivec2(dx, dy), glm::ivec2(0), last);
        const Image depth = filled(1, [&](int x, int y) {
          return std::vector<float>{glm::ivec2(x, y) == near ? 1.0f : 5.0f};
        });
        resolver.resetHistory();
        run(resolver, grey(0.5f), &depth, &motion);
        const float* velocity = resolver.lastDebug().at(p.x, p.y) + 2;
        EXPECT_FLOAT_EQ(velocity[0], motion.at(near.x, near.y)[0])
            << "pixel " << p.x << "," << p.y << " nearest at " << near.x << "," << near.y;
        EXPECT_FLOAT_EQ(velocity[1], motion.at(near.x, near.y)[1])
            << "pixel " << p.x << "," << p.y << " nearest at " << near.x << "," << near.y;
      }
    }
  }
}

// Disocclusion needs every texel of the previous 3x3 to be nearer: one texel that still shows the
// surface, in any of the nine places, keeps history.
TEST_F(StagesTest, OneAgreeingPreviousTexelAnywhereInTheFootprintKeepsHistory) {
  ResolveOptions o = plainOptions();
  o.rectify = Rectify::None;
  Resolver resolver(*context_, o);
  resolver.setDebugOutput(true);
  const Image surface = constant(1, 5.0f);
  const glm::ivec2 p(9, 5);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      // The previous frame: something nearer everywhere but at one texel of p's footprint.
      const Image previous = filled(1, [&](int x, int y) {
        return std::vector<float>{x == p.x + dx && y == p.y + dy ? 5.0f : 1.0f};
      });
      resolver.resetHistory();
      run(resolver, grey(0.0f), &previous);
      run(resolver, grey(1.0f), &surface);
      EXPECT_EQ(resolver.lastDebug().at(p.x, p.y)[1], float(Rejection::Kept))
          << "agreeing texel at " << dx << "," << dy;
      EXPECT_EQ(resolver.lastDebug().at(p.x + 4, p.y)[1], float(Rejection::Disoccluded));
    }
  }
}

// Lanczos-2's negative lobe rings beside a bright edge, below zero here; anti-ringing keeps the
// reconstruction within the 3x3 samples' range.
TEST_F(StagesTest, AntiRingingKeepsTheReconstructionWithinItsSamples) {
  ResolveOptions o = plainOptions();
  o.reconstruction = Reconstruction::Lanczos2;
  const Image edge = filled(4, [](int x, int) {
    const float v = x >= 12 ? 10.0f : 0.1f;
    return std::vector<float>{v, v, v, 1};
  });
  // Samples 0.4 px right of their centres: pixel 11's right neighbour, the first bright one,
  // sits 1.4 px away, in Lanczos-2's negative lobe.
  const glm::vec2 jitter(0.4f, 0.0f);
  Resolver ringing(*context_, o);
  EXPECT_LT(run(ringing, edge, nullptr, nullptr, jitter).at(11, 6)[0], 0.0f);
  o.antiRinging = true;
  Resolver clamped(*context_, o);
  const Image out = run(clamped, edge, nullptr, nullptr, jitter);
  for (int x = 0; x < kWidth; ++x) {
    EXPECT_GE(out.at(x, 6)[0], 0.1f) << "x " << x;
    EXPECT_LE(out.at(x, 6)[0], 10.0f) << "x " << x;
  }
}

TEST_F(StagesTest, ColourFarOutsideTheBoxIsClippedToItsSurface) {
  for (Rectify mode : {Rectify::Clamp, Rectify::Clip, Rectify::VarianceClip}) {
    ResolveOptions o = plainOptions();
    o.rectify = mode;
    o.blend = 0.05f;
    Resolver resolver(*context_, o);
    run(resolver, grey(50.0f));  // history far brighter than anything in the next frame
    const Image checker = filled(4, [](int x, int y) {
      const float v = (x + y) % 2 ? 0.2f : 0.4f;
      return std::vector<float>{v, v, v, 1};
    });
    const Image out = run(resolver, checker);
    for (int x = 1; x < kWidth - 1; ++x) {
      // The 3x3 box spans [0.2, 0.4]: rectified history lies on its upper surface (0.4) or
      // inside, so the blend cannot exceed it.
      EXPECT_LE(out.at(x, 5)[0], 0.4f + 1e-5f) << int(mode) << " x=" << x;
      EXPECT_GE(out.at(x, 5)[0], 0.2f - 1e-5f) << int(mode) << " x=" << x;
    }
    if (mode == Rectify::Clamp) {  // clamped history is exactly the box's top: 0.95*0.4 + 0.05*c
      EXPECT_NEAR(out.at(5, 5)[0], 0.95f * 0.4f + 0.05f * 0.4f, 1e-5f);
    }
  }
}

TEST_F(StagesTest, StaticJitteredEdgeConvergesToItsCoverage) {
  ResolveOptions o = plainOptions();
  o.jitter.source = JitterSource::Halton;
  o.sampleCount = true;  // an exact running mean for the first 1/blend frames
  o.blend = 0.01f;
  Resolver resolver(*context_, o);
  const double edge = 10.3;  // pixel 10 spans [10, 11): 30% of it is left of the edge (white)
  Image out;
  for (int frame = 1; frame <= 64; ++frame) {
    const glm::vec2 j = frameJitter(frame, o.jitter);
    const Image color = filled(4, [&](int x, int) {
      const float v = x + 0.5 + j.x < edge ? 1.0f : 0.0f;
      return std::vector<float>{v, v, v, 1};
    });
    out = run(resolver, color, nullptr, nullptr, j);
  }
  EXPECT_NEAR(out.at(10, 6)[0], 0.3f, 0.03f);
  EXPECT_FLOAT_EQ(out.at(9, 6)[0], 1.0f);
  EXPECT_FLOAT_EQ(out.at(11, 6)[0], 0.0f);
}

TEST_F(StagesTest, SampleCountMakesNewHistoryConvergeAtOnce) {
  for (bool count : {true, false}) {
    ResolveOptions o = plainOptions();
    o.sampleCount = count;
    o.rectify = Rectify::None;
    Resolver resolver(*context_, o);
    run(resolver, grey(0.0f));
    const Image out = run(resolver, grey(1.0f));
    // Two samples so far: with the count, each weighs 1/2; without, the current weighs blend.
    EXPECT_NEAR(out.at(5, 5)[0], count ? 0.5f : 0.1f, 1e-6f);
  }
}

TEST_F(StagesTest, VelocityBlendFavoursTheCurrentFrameWhenMoving) {
  ResolveOptions o = plainOptions();
  o.rectify = Rectify::None;
  o.velocityBlend = 0.6f;
  o.velocityScale = 4.0f;
  Resolver resolver(*context_, o);
  run(resolver, grey(0.0f));
  // Left half moves 8 px/frame (beyond the scale), right half 2 px (half-way), both from the
  // left so the previous position stays on screen.
  const Image motion = filled(2, [](int x, int) {
    return std::vector<float>{x < 12 ? 8.0f : 2.0f, 0.0f};
  });
  const Image out = run(resolver, grey(1.0f), nullptr, &motion);
  EXPECT_NEAR(out.at(3, 5)[0], 0.6f, 1e-5f);
  EXPECT_NEAR(out.at(16, 5)[0], 0.5f * (0.1f + 0.6f), 1e-5f);
}

TEST_F(StagesTest, AntiFlickerTrustsAgreeingHistoryMore) {
  ResolveOptions o = plainOptions();
  o.rectify = Rectify::None;
  o.antiFlicker = 0.5f;
  Resolver resolver(*context_, o);
  run(resolver, grey(1.0f));
  const Image out = run(resolver, grey(1.0f + 1e-6f));  // agreeing luma: weight 0.1 * (1 - 0.5)
  EXPECT_NEAR(out.at(5, 5)[0] - 1.0f, 0.05f * 1e-6f, 1e-7f);
  Resolver other(*context_, o);
  run(other, grey(0.0f));
  const Image changed = run(other, grey(1.0f));  // fully disagreeing luma: the base weight
  EXPECT_NEAR(changed.at(5, 5)[0], 0.1f, 1e-6f);
}

TEST_F(StagesTest, LumaWeightingTamesAFirefly) {
  ResolveOptions o = plainOptions();
  o.rectify = Rectify::None;
  o.lumaWeighting = true;
  o.blend = 0.5f;
  Resolver resolver(*context_, o);
  run(resolver, grey(1.0f));
  const Image out = run(resolver, grey(99.0f));
  // Weights 0.5/(1+1) and 0.5/(1+99): (0.25 * 1 + 0.005 * 99) / 0.255.
  EXPECT_NEAR(out.at(5, 5)[0], (0.25f + 0.005f * 99.0f) / 0.255f, 1e-3f);
}

TEST_F(StagesTest, CameraMotionFillsZeroVectorsOnTheSky) {
  ResolveOptions o = plainOptions();
  o.cameraMotion = CameraMotion::Fill;
  Resolver resolver(*context_, o);
  resolver.setDebugOutput(true);
  // A camera yawing 2 degrees per frame; nothing is hit (sky), vectors are zero as Cycles writes.
  auto cameraAt = [](double yawDegrees) {
    FrameCamera c;
    c.worldToCamera = glm::rotate(glm::dmat4(1.0), glm::radians(yawDegrees), glm::dvec3(0, 1, 0));
    // A +z-forward perspective onto NDC x, y in [0, 1], y down: x' = 0.5 + 0.5 x / (z tan),
    // y' = 0.5 - 0.5 y / (z tan) (aspect 2:1), w = z.
    const double t = std::tan(glm::radians(30.0));
    glm::dmat4 p(0.0);
    p[0][0] = 0.5 / t;
    p[1][1] = -0.5 / (t / 2.0);
    p[2][0] = 0.5;
    p[2][1] = 0.5;
    p[2][2] = 1.0;
    p[3][2] = -0.1;
    p[2][3] = 1.0;
    c.worldToNdc = p * c.worldToCamera;
    return c;
  };
  const FrameCamera first = cameraAt(0.0), second = cameraAt(2.0);
  const Image sky = constant(1, INFINITY);
  const Image zero = constant(2, 0.0f);
  run(resolver, grey(0.5f), &sky, &zero, {0, 0}, &first);
  run(resolver, grey(0.5f), &sky, &zero, {0, 0}, &second);
  const RasterWindow window{0, 0, kWidth, kHeight};
  for (int x : {2, 12, 21}) {
    const glm::dvec2 expected = cameraMotion(second, first, window, NdcConvention::ZeroOneYDown,
                                             glm::dvec2(x + 0.5, 6.5), INFINITY);
    EXPECT_GT(std::abs(expected.x), 0.3);  // the yaw really moves the sky
    EXPECT_NEAR(resolver.lastDebug().at(x, 6)[2], expected.x, 1e-3) << x;
    EXPECT_NEAR(resolver.lastDebug().at(x, 6)[3], expected.y, 1e-3) << x;
  }
  // With vectors only, the sky keeps its zero vectors.
  o.cameraMotion = CameraMotion::Vectors;
  resolver.setOptions(o);
  run(resolver, grey(0.5f), &sky, &zero, {0, 0}, &first);
  EXPECT_EQ(resolver.lastDebug().at(12, 6)[2], 0.0f);
}

TEST_F(StagesTest, ThinFeatureHoldKeepsHistoryTheBoxWouldClip) {
  for (float hold : {0.0f, 1.0f}) {
    ResolveOptions o = plainOptions();
    o.thinFeatureHold = hold;
    o.rectify = Rectify::Clamp;
    Resolver resolver(*context_, o);
    const Image depth = constant(1, 3.0f);
    // Frame 1 saw a bright sub-pixel wire in column 8; frame 2's sample missed it.
    const Image wire = filled(4, [](int x, int) {
      const float v = x == 8 ? 1.0f : 0.0f;
      return std::vector<float>{v, v, v, 1};
    });
    run(resolver, wire, &depth);
    const Image out = run(resolver, grey(0.0f), &depth);
    if (hold == 0.0f) {
      EXPECT_FLOAT_EQ(out.at(8, 6)[0], 0.0f);  // clamped into the all-black box: the wire is gone
    } else {
      EXPECT_NEAR(out.at(8, 6)[0], 0.9f, 1e-5f);  // depth-confirmed and static: held
    }
  }
}

TEST_F(StagesTest, SharpenNeverReachesHistory) {
  const Image ramp = filled(4, [](int x, int y) {
    const float v = float((x * 7 + y * 3) % 5) * 0.2f;
    return std::vector<float>{v, v, v, 1};
  });
  ResolveOptions o = plainOptions();
  Resolver plain(*context_, o);
  o.sharpen = 1.0f;
  Resolver sharpened(*context_, o);
  EXPECT_NE(run(sharpened, ramp).pixels, run(plain, ramp).pixels);  // it changes the output ...
  o.sharpen = 0.0f;
  sharpened.setOptions(o);
  const Image c = run(sharpened, grey(0.5f));
  Resolver reference(*context_, plainOptions());
  run(reference, ramp);
  EXPECT_EQ(c.pixels, run(reference, grey(0.5f)).pixels);  // ... but not what history holds
}

TEST_F(StagesTest, CatmullRomHistoryStaysSharperThanBilinear) {
  // A hard vertical edge moving 0.5 px per frame (exact motion, no jitter, no rectification):
  // every frame resamples history half-way between texels, where bilinear blurs most.
  double steepest[2] = {0.0, 0.0};
  for (HistoryFilter filter : {HistoryFilter::Bilinear, HistoryFilter::CatmullRom}) {
    ResolveOptions o = plainOptions();
    o.historyFilter = filter;
    o.rectify = Rectify::None;
    Resolver resolver(*context_, o);
    const Image motion = filled(2, [](int, int) { return std::vector<float>{-0.5f, 0.0f}; });
    Image out;
    for (int frame = 0; frame < 12; ++frame) {
      const double edge = 6.0 + 0.5 * frame;
      const Image color = filled(4, [&](int x, int) {
        const float v = float(std::clamp(edge - x, 0.0, 1.0));  // exact pixel coverage
        return std::vector<float>{v, v, v, 1};
      });
      out = run(resolver, color, nullptr, frame ? &motion : nullptr);
    }
    for (int x = 1; x < kWidth; ++x) {
      steepest[int(filter)] =
          std::max(steepest[int(filter)], double(out.at(x - 1, 6)[0] - out.at(x, 6)[0]));
    }
  }
  EXPECT_GT(steepest[int(HistoryFilter::CatmullRom)], steepest[int(HistoryFilter::Bilinear)] + 0.05)
      << "bilinear " << steepest[0] << ", Catmull-Rom " << steepest[1];
}

TEST_F(StagesTest, CutDetectionResetsWhenMostHistoryIsRejected) {
  ResolveOptions o = plainOptions();
  o.cutDetection = 0.5f;
  Resolver resolver(*context_, o);
  const Image near = constant(1, 1.0f), far = constant(1, 20.0f);
  run(resolver, grey(0.0f), &near);
  run(resolver, grey(0.0f), &near);
  EXPECT_FALSE(resolver.lastFrameWasCut());
  const Image out = run(resolver, grey(1.0f), &far);  // another view: every depth test fails
  EXPECT_TRUE(resolver.lastFrameWasCut());
  EXPECT_FLOAT_EQ(out.at(5, 5)[0], 1.0f);
}

}  // namespace
}  // namespace taa
