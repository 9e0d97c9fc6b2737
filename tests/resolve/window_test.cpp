// The window resolve on tiny analytic scenes (real GL, llvmpipe here): each scene is point
// sampled at every frame's Halton jitter through a pinhole camera, with exact depth, motion
// vectors and camera matrices, so the output can be held against the box-filtered truth.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <cstring>

#include "taa/error.h"

#include "gl/context.h"
#include "resolve/camera.h"
#include "resolve/jitter.h"
#include "resolve/window_resolver.h"
#include "util/frame_buffer_pool.h"

namespace taa {
namespace {

constexpr int kWidth = 40, kHeight = 16;
constexpr double kFocal = 40.0;  // pixels
constexpr double kNear = 0.1, kFar = 1000.0;

// What a ray hits: its colour and planar depth.
struct Hit {
  float colour = 0.0f;
  double depth = 0.0;
};

// A scene of layers at constant depths seen by a camera at (cameraX(frame), 0, 0) looking down
// +z; world y points down like raster y. `hit(frame, X, depth-ordered query)` answers what the
// ray through raster (x, y) meets; `motionOf` is the surface's own motion in world X per frame
// (0 for static layers).
struct Scene {
  std::function<double(int frame)> cameraX = [](int) { return 0.0; };
  // The nearest hit along the ray through raster (x, y) at `frame`, and the world X per frame
  // the hit surface moves by (its motion).
  std::function<Hit(int frame, double x, double y, double& movesX)> trace;
  bool withCameras = true;
};

double worldXAt(double rasterX, double depth, double cameraX) {
  return cameraX + (rasterX - kWidth / 2.0) * depth / kFocal;
}

double rasterXOf(double worldX, double depth, double cameraX) {
  return kWidth / 2.0 + kFocal * (worldX - cameraX) / depth;
}

FrameCamera cameraAt(double x) {
  FrameCamera camera;
  camera.worldToCamera = glm::dmat4(1.0);
  camera.worldToCamera[3][0] = -x;
  // NDC (0..1 over the display window, y down): x = 0.5 + f X / (W Z), y = 0.5 + f Y / (H Z).
  glm::dmat4 projection(0.0);  // column-major
  projection[0][0] = kFocal / kWidth;
  projection[1][1] = kFocal / kHeight;
  projection[2][0] = 0.5;
  projection[2][1] = 0.5;
  projection[2][2] = kFar / (kFar - kNear);
  projection[3][2] = -kFar * kNear / (kFar - kNear);
  projection[2][3] = 1.0;
  camera.worldToNdc = projection * camera.worldToCamera;
  return camera;
}

struct Frame {
  Image color, depth, motion;
  glm::vec2 jitter;
  FrameCamera camera;
};

Frame render(const Scene& scene, int frame) {
  Frame out{Image(kWidth, kHeight, 4), Image(kWidth, kHeight, 1), Image(kWidth, kHeight, 2),
            frameJitter(frame, JitterOptions{}), cameraAt(scene.cameraX(frame))};
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const double sx = x + 0.5 + out.jitter.x, sy = y + 0.5 + out.jitter.y;
      double movesX = 0.0;
      const Hit hit = scene.trace(frame, sx, sy, movesX);
      float* c = out.color.at(x, y);
      c[0] = c[1] = c[2] = hit.colour;
      c[3] = 1.0f;
      out.depth.at(x, y)[0] = float(hit.depth);
      // Where the sample's point was one frame ago: it moved by movesX, the camera by the
      // difference of its positions.
      const double worldX = worldXAt(sx, hit.depth, scene.cameraX(frame));
      const double previous = rasterXOf(worldX - movesX, hit.depth, scene.cameraX(frame - 1));
      out.motion.at(x, y)[0] = float(previous - sx);
      out.motion.at(x, y)[1] = 0.0f;
    }
  }
  return out;
}

// The box-filtered truth of pixel (x, y) at `frame` (32x32 samples).
float truth(const Scene& scene, int frame, int x, int y) {
  double sum = 0.0;
  for (int j = 0; j < 32; ++j) {
    for (int i = 0; i < 32; ++i) {
      double movesX = 0.0;
      sum += scene.trace(frame, x + (i + 0.5) / 32.0, y + (j + 0.5) / 32.0, movesX).colour;
    }
  }
  return float(sum / 1024.0);
}

ResolveOptions windowOptions(int radius) {
  ResolveOptions o;
  o.mode = ResolveMode::Window;
  o.window.radius = radius;
  o.color.bracket = "none";
  return o;
}

// The means over a patch of a frame resolved with some options and with one changed.
struct PatchMeans {
  double asGiven, changed;
};

class WindowTest : public ::testing::Test {
 protected:
  void SetUp() override { context_ = gl::Context::create(gl::Backend::Auto); }

  // The means over x0..x1, y0..y1 of `frame` resolved with `options` and with `change` made to
  // them.
  PatchMeans patchMeans(const Scene& scene, int frame, ResolveOptions options,
                        const std::function<void(ResolveOptions&)>& change, int x0, int x1,
                        int y0, int y1);

  // Resolves `frame` from frames frame-K..frame+K of the scene, on a resolver holding only them.
  Image resolve(const Scene& scene, int frame, const ResolveOptions& options) {
    WindowResolver resolver(*context_, options);
    return resolveWith(resolver, scene, frame, options.window.radius);
  }

  // With `colourAsPass`, each frame's colour is also its one pass group (setPasses): the
  // group's sums, resolved as a pass, go to *colourAsPass.
  Image resolveWith(WindowResolver& resolver, const Scene& scene, int frame, int radius,
                    Image* colourAsPass = nullptr) {
    const int first = frame - radius, last = frame + radius;
    if (colourAsPass) resolver.setPasses({false}, 0);
    for (int f = first; f <= last; ++f) {
      if (resolver.hasFrame(f)) continue;
      const Frame data = render(scene, f);
      ResolveInput input;
      input.color = &data.color;
      if (colourAsPass) input.passGroups = {&data.color};
      input.depth = &data.depth;
      input.motion = &data.motion;
      input.jitter = data.jitter;
      input.camera = scene.withCameras ? &data.camera : nullptr;
      input.window = {0, 0, kWidth, kHeight};
      input.ndc = NdcConvention::ZeroOneYDown;
      resolver.addFrame(f, input);
    }
    Image resolved = std::move(*resolver.resolve(frame, first, last, SampleType::Float).floats());
    if (colourAsPass) {
      PassSums sums = resolver.takePassSums();
      *colourAsPass = std::move(*sums.groups.at(0).floats());
    }
    return resolved;
  }

  std::unique_ptr<gl::Context> context_;
};

// A vertical edge between 0 and 1 at x = 20.3, still: pixel 20 is 70% covered.
Scene staticEdge() {
  Scene scene;
  scene.trace = [](int, double x, double, double&) { return Hit{x >= 20.3 ? 1.0f : 0.0f, 5.0}; };
  return scene;
}

TEST_F(WindowTest, StaticJitteredEdgeConvergesToItsCoverage) {
  const Scene scene = staticEdge();
  const Image out = resolve(scene, 20, windowOptions(8));
  for (int y = 2; y < kHeight - 2; ++y) {
    EXPECT_NEAR(out.at(20, y)[0], truth(scene, 20, 20, y), 0.05f) << "y " << y;
    EXPECT_NEAR(out.at(15, y)[0], 0.0f, 1e-6f);
    EXPECT_NEAR(out.at(25, y)[0], 1.0f, 1e-6f);
  }
  // One frame alone cannot say: its sample at x + 0.5 + jitter is all or nothing.
  const Image alone = resolve(scene, 20, windowOptions(0));
  EXPECT_GT(std::fabs(alone.at(20, 8)[0] - truth(scene, 20, 20, 8)), 0.1f);
}

// An orthographic camera panning 0.37 px a frame over a still edge between 0 and 1 at world x
// 0.3 (raster x 20.3 at frame 20): its rays do not meet at its origin, so its samples take the
// camera carry's general form (the gather's pinhole form, which leaves the carry's offset out,
// would put them up to the pan's whole length off).
TEST_F(WindowTest, AnOrthographicCamerasSamplesAreCarriedByItsRays) {
  constexpr double kScale = 40.0;  // raster pixels per world unit
  const auto cameraX = [](int frame) { return (frame - 20) * 0.37 / kScale; };
  const auto colourAt = [&](int frame, double rasterX) {
    return (rasterX - kWidth / 2.0) / kScale + cameraX(frame) >= 0.3 / kScale ? 1.0f : 0.0f;
  };
  const auto camera = [&](int frame) {
    FrameCamera c;
    c.worldToCamera = glm::dmat4(1.0);
    c.worldToCamera[3][0] = -cameraX(frame);
    glm::dmat4 projection(1.0);  // NDC 0..1, y down, w = 1
    projection[0][0] = kScale / kWidth;
    projection[3][0] = 0.5;
    projection[1][1] = kScale / kHeight;
    projection[3][1] = 0.5;
    projection[2][2] = 1.0 / (kFar - kNear);
    projection[3][2] = -kNear / (kFar - kNear);
    c.worldToNdc = projection * c.worldToCamera;
    return c;
  };
  ASSERT_FALSE(isPinhole(camera(20), {0, 0, kWidth, kHeight}, NdcConvention::ZeroOneYDown));
  const auto resolveAt = [&](int radius) {
    WindowResolver resolver(*context_, windowOptions(radius));
    for (int f = 20 - radius; f <= 20 + radius; ++f) {
      const glm::vec2 jitter = frameJitter(f, JitterOptions{});
      Image color(kWidth, kHeight, 4), depth(kWidth, kHeight, 1), motion(kWidth, kHeight, 2);
      for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
          float* c = color.at(x, y);
          c[0] = c[1] = c[2] = colourAt(f, x + 0.5 + jitter.x);
          c[3] = 1.0f;
          depth.at(x, y)[0] = 5.0f;
          motion.at(x, y)[0] = 0.37f;  // the point was 0.37 px to the right a frame before
          motion.at(x, y)[1] = 0.0f;
        }
      }
      const FrameCamera frameCamera = camera(f);
      ResolveInput input;
      input.color = &color;
      input.depth = &depth;
      input.motion = &motion;
      input.jitter = jitter;
      input.camera = &frameCamera;
      input.window = {0, 0, kWidth, kHeight};
      input.ndc = NdcConvention::ZeroOneYDown;
      resolver.addFrame(f, input);
    }
    return std::move(*resolver.resolve(20, 20 - radius, 20 + radius, SampleType::Float).floats());
  };
  const Image out = resolveAt(8);
  for (int y = 2; y < kHeight - 2; ++y) {
    EXPECT_NEAR(out.at(20, y)[0], 0.7f, 0.05f) << "y " << y;
    EXPECT_NEAR(out.at(16, y)[0], 0.0f, 1e-3f);
    EXPECT_NEAR(out.at(24, y)[0], 1.0f, 1e-3f);
  }
  const Image alone = resolveAt(0);
  EXPECT_GT(std::fabs(alone.at(20, 8)[0] - 0.7f), 0.1f);
}

TEST_F(WindowTest, WithoutCamerasTheVectorsCarryTheSamples) {
  // The edge moves 2 px a frame, said by the vectors alone: no camera matrices.
  Scene scene;
  scene.withCameras = false;
  scene.trace = [](int frame, double x, double, double& movesX) {
    movesX = 2.0 * 5.0 / kFocal;  // 2 px at depth 5
    return Hit{x >= 7.3 + 2.0 * frame ? 1.0f : 0.0f, 5.0};
  };
  const int frame = 6;
  const Image out = resolve(scene, frame, windowOptions(8));
  const int x = 19;  // the edge is at 19.3 in frame 6
  for (int y = 2; y < kHeight - 2; ++y) {
    EXPECT_NEAR(out.at(x, y)[0], truth(scene, frame, x, y), 0.05f) << "y " << y;
    EXPECT_NEAR(out.at(x - 3, y)[0], 0.0f, 1e-3f);
    EXPECT_NEAR(out.at(x + 3, y)[0], 1.0f, 1e-3f);
  }
}

// A 0.3 px wire at depth 2, slanting 0.15 px a row, before a striped backdrop at depth 20
// (stripes 3 px wide); the camera slides, so the backdrop moves past the wire. Each frame's own
// samples hit the wire in some rows only; the window must find it in the other frames' samples
// and keep the backdrop beside it.
constexpr double kWireWidth = 0.3 * 2.0 / kFocal;  // 0.3 px at depth 2
constexpr double kWireSlope = 0.15;                // world x per world y

// A bar at depth 2 (colour 1), leaning kWireSlope, before a striped backdrop (depth 20): at each
// row it covers world x offsets [left, left + width). The camera slides `speed` a frame and is at
// `cameraAt10` on frame 10.
Scene barBeforeBackdrop(double left, double width, double speed, double cameraAt10) {
  Scene scene;
  const auto camera = [speed, cameraAt10](int frame) { return cameraAt10 + speed * (frame - 10); };
  scene.cameraX = camera;
  scene.trace = [=](int frame, double x, double y, double&) {
    const double barX = worldXAt(x, 2.0, camera(frame));
    const double barY = (y - kHeight / 2.0) * 2.0 / kFocal;
    const double offset = barX - kWireSlope * barY;
    if (offset >= left && offset < left + width) return Hit{1.0f, 2.0};
    const double backdropX = worldXAt(x, 20.0, camera(frame));
    const double stripe = std::floor(backdropX / (3.0 * 20.0 / kFocal));
    return Hit{std::fmod(std::fabs(stripe), 2.0) == 0.0 ? 0.3f : 0.1f, 20.0};
  };
  return scene;
}

// The 0.3 px wire; `speed`: the camera's slide a frame; at frame 10 it is at 0.5 whatever the
// speed (the wire at x 10).
Scene wireBeforeBackdrop(double speed = 0.05) {
  return barBeforeBackdrop(0.0, kWireWidth, speed, 0.5);
}

TEST_F(WindowTest, ThinFeatureBeforeAMovingBackdropSurvives) {
  const Scene scene = wireBeforeBackdrop();
  const int frame = 10;
  const Image out = resolve(scene, frame, windowOptions(8));
  const Image alone = resolve(scene, frame, windowOptions(0));
  const int centre = int(std::floor(rasterXOf(0.0, 2.0, scene.cameraX(frame))));
  double outError = 0.0, aloneError = 0.0;
  int rows = 0;
  for (int y = 3; y < kHeight - 3; ++y, ++rows) {
    // The wire's energy in its row: the columns around it together.
    double sumOut = 0.0, sumAlone = 0.0, sumTruth = 0.0;
    for (int x = centre - 3; x <= centre + 3; ++x) {
      sumOut += out.at(x, y)[0];
      sumAlone += alone.at(x, y)[0];
      sumTruth += truth(scene, frame, x, y);
    }
    outError += std::fabs(sumOut - sumTruth);
    aloneError += std::fabs(sumAlone - sumTruth);
    EXPECT_NEAR(sumOut, sumTruth, 0.25) << "row " << y;
    // The backdrop well beside the wire is untouched by it.
    EXPECT_NEAR(out.at(centre + 6, y)[0], truth(scene, frame, centre + 6, y), 0.06f);
  }
  EXPECT_LT(outError, 0.5 * aloneError) << "mean error per row " << outError / rows;
}

// The error of the wire's energy per row (the columns within `reach` of it), summed over rows
// (as above).
double wireEnergyError(const Scene& scene, int frame, const Image& out, int reach = 3) {
  const int centre = int(std::floor(rasterXOf(0.0, 2.0, scene.cameraX(frame))));
  double error = 0.0;
  for (int y = 3; y < kHeight - 3; ++y) {
    double sumOut = 0.0, sumTruth = 0.0;
    for (int x = centre - reach; x <= centre + reach; ++x) {
      sumOut += out.at(x, y)[0];
      sumTruth += truth(scene, frame, x, y);
    }
    error += std::fabs(sumOut - sumTruth);
  }
  return error;
}

// The same wire under three times the slide: it moves 3 px a frame and the backdrop 0.3, so in
// the nearest frames the wire's samples already lie 2.7 px from the backdrop's. Rows whose own
// 3x3 missed the wire find its depth in t's samples of the rows around (--window-thin-search)
// and ask every frame for its samples there.
TEST_F(WindowTest, AWireTheRowsOwnSamplesMissedIsFoundUnderLargeParallax) {
  const Scene scene = wireBeforeBackdrop(0.15);
  const int frame = 10;
  ResolveOptions options = windowOptions(4);
  ASSERT_GT(options.window.thinSearchRadius, 1);  // the default
  const double searched = wireEnergyError(scene, frame, resolve(scene, frame, options));
  options.window.thinSearchRadius = 0;
  const double missed = wireEnergyError(scene, frame, resolve(scene, frame, options));
  const double alone = wireEnergyError(scene, frame, resolve(scene, frame, windowOptions(0)));
  // Measured: 0.89, 1.69 with the 3x3 alone, 3.32 for frame 10 alone.
  EXPECT_LT(searched, 0.6 * missed) << "searched " << searched << ", the 3x3 alone " << missed;
  EXPECT_LT(searched, 0.35 * alone) << "searched " << searched << ", frame 10 alone " << alone;
}

// A bar 3.2 px wide (depth 2, colour 1) before a striped backdrop (depth 20) under a pan that
// moves the bar 4 px a frame and the backdrop 0.4, as a 1080p render's chain-link does. Pixels
// inside the bar whose 3x3 reaches the backdrop hold both depths, so the backdrop's carried
// samples pass the 3x3's test; t's own sample nearest where each lands says the bar covers it
// (docs/TUNING.md, "Wide occluders").
Scene wideBarBeforeBackdrop() {
  return barBeforeBackdrop(-0.08, 0.16, 0.2, 0.0);  // 3.2 px at depth 2
}

TEST_F(WindowTest, AWideBarKeepsTheBackdropsSamplesOutOfItsInside) {
  const Scene scene = wideBarBeforeBackdrop();
  const int frame = 10;
  const Image out = resolve(scene, frame, windowOptions(8));
  double inside = 0.0, outside = 0.0;
  int insideCount = 0, outsideCount = 0;
  for (int y = 2; y < kHeight - 2; ++y) {
    for (int x = 2; x < kWidth - 2; ++x) {
      const float expected = truth(scene, frame, x, y);
      const double error = std::fabs(out.at(x, y)[0] - expected);
      if (expected > 0.999f) {  // wholly inside the bar
        inside += error;
        ++insideCount;
      } else {
        outside += error;
        ++outsideCount;
      }
    }
  }
  ASSERT_GT(insideCount, 2 * (kHeight - 4));  // two or more whole pixels a row
  // Measured: 0.020 inside (0.014 outside); 0.23 (0.019) when only the 3x3's farthest depth hid
  // samples.
  EXPECT_LT(inside / insideCount, 0.05) << "mean error inside the bar, " << insideCount
                                        << " pixels; outside " << outside / outsideCount;
}

// A bar 1.5 px wide under the same pan: t's samples hit it in one or two columns a row, too few
// for the test above, so the backdrop's samples that land inside it (from frames where it
// stood 4 px a frame elsewhere) pass every test. In two clusters (--window-two-clusters) the
// bar's samples and the backdrop's are averaged apart and mixed by the bar's coverage, which
// those samples do not dilute (docs/TUNING.md, "Two clusters"): its energy a row as the truth's.
TEST_F(WindowTest, ABarAPixelAndAHalfWideKeepsItsWidthInTwoClusters) {
  const Scene scene = barBeforeBackdrop(-0.0375, 0.075, 0.2, 0.0);  // 1.5 px at depth 2
  const int frame = 10;
  ResolveOptions options = windowOptions(8);
  ASSERT_TRUE(options.window.twoClusters);  // the default
  const double clustersError = wireEnergyError(scene, frame, resolve(scene, frame, options), 4);
  options.window.twoClusters = false;
  const double plainError = wireEnergyError(scene, frame, resolve(scene, frame, options), 4);
  // Measured: 0.75 in two clusters, 4.39 with the plain mean.
  EXPECT_LT(clustersError, 0.5 * plainError)
      << "the bar's energy, error summed over rows: two clusters " << clustersError
      << ", the plain mean " << plainError;
}

// The same bar, moving itself (2 px a frame) before the still backdrop under a still camera:
// its samples reach t along the chains. A pixel on its edge whose centre lies off the bar has
// a chain carried by the bar's motion that lands beside the bar's samples in every frame, on
// the backdrop; the chain goes on with the motion of its block's nearest moving sample, so
// such pixels gather the bar's samples from the whole moving window, not from t alone.
Scene movingBarBeforeBackdrop() {
  Scene scene;
  scene.trace = [](int frame, double x, double y, double& movesX) {
    constexpr double kLeft = -0.0375, kBarWidth = 0.075, kSpeed = 0.1;  // 1.5 px, 2 px a frame
    const double barX = worldXAt(x, 2.0, 0.0) - kSpeed * (frame - 10);
    const double barY = (y - kHeight / 2.0) * 2.0 / kFocal;
    const double offset = barX - kWireSlope * barY;
    if (offset >= kLeft && offset < kLeft + kBarWidth) {
      movesX = kSpeed;
      return Hit{1.0f, 2.0};
    }
    const double stripe = std::floor(worldXAt(x, 20.0, 0.0) / (3.0 * 20.0 / kFocal));
    return Hit{std::fmod(std::fabs(stripe), 2.0) == 0.0 ? 0.3f : 0.1f, 20.0};
  };
  return scene;
}

TEST_F(WindowTest, AMovingBarsEdgesGatherItsSamplesFromTheWholeWindow) {
  const Scene scene = movingBarBeforeBackdrop();
  const int frame = 10;  // the bar's centre at x 20, as the static bar's
  const double error = wireEnergyError(scene, frame, resolve(scene, frame, windowOptions(8)), 4);
  // Measured: 1.83; 2.46 when a chain ended where its point first landed off the bar, 2.27
  // when it ended there but its last block still counted.
  EXPECT_LT(error, 2.1) << "the bar's energy, error summed over rows";
}

// The passes are weighed as the beauty is, two clusters included (window_gather.frag's shares):
// with the colour given again as a pass, the bar's beauty is the beauty without passes, bit
// for bit, and the pass is that beauty (without the reconstruction's taps, which the beauty
// clamps and a pass cannot). Before, a run with passes took the plain mean for both.
TEST_F(WindowTest, PassesFollowTheBarsTwoClusters) {
  const Scene scene = barBeforeBackdrop(-0.0375, 0.075, 0.2, 0.0);
  const int frame = 10;
  ResolveOptions options = windowOptions(8);
  options.window.reconstructionWeight = 0.0f;
  options.window.regionTolerance = 0.0f;  // a run with passes has no region test (its memory)
  const Image alone = resolve(scene, frame, options);
  Image pass;
  WindowResolver withPasses(*context_, options);
  const Image beauty = resolveWith(withPasses, scene, frame, 8, &pass);
  options.window.twoClusters = false;
  const Image plain = resolve(scene, frame, options);
  ASSERT_EQ(pass.pixels.size(), beauty.pixels.size());
  std::size_t clustered = 0;
  for (std::size_t i = 0; i < beauty.pixels.size(); ++i) {
    ASSERT_EQ(beauty.pixels[i], alone.pixels[i]) << "value " << i;
    ASSERT_NEAR(pass.pixels[i], beauty.pixels[i], 1e-5f * std::abs(beauty.pixels[i]) + 1e-7f)
        << "value " << i;
    clustered += std::abs(beauty.pixels[i] - plain.pixels[i]) > 1e-3f;
  }
  EXPECT_GT(clustered, std::size_t(2 * kHeight));  // the bar's edges, every row
}

// A box (depth 1, colour 1) moving 2 px a frame right over a still backdrop (depth 10, 0.2),
// static camera: what it leaves behind and what it is about to cover must show the backdrop.
Scene movingBox() {
  Scene scene;
  scene.trace = [](int frame, double x, double y, double& movesX) {
    const double left = 4.0 + 2.0 * frame;
    if (x >= left && x < left + 8.0 && y >= 4.0 && y < 12.0) {
      movesX = 2.0 * 1.0 / kFocal;  // 2 px at depth 1
      return Hit{1.0f, 1.0};
    }
    return Hit{0.2f, 10.0};
  };
  return scene;
}

TEST_F(WindowTest, AnObjectRevealingTheBackgroundLeavesNoGhost) {
  const Scene scene = movingBox();
  const int frame = 8;  // the box covers x 20..28
  const Image out = resolve(scene, frame, windowOptions(6));
  for (int x : {14, 16, 18, 30, 32, 34}) {  // covered before or after, not now
    EXPECT_NEAR(out.at(x, 8)[0], 0.2f, 0.02f) << "x " << x;
  }
  for (int x : {21, 24, 26}) EXPECT_NEAR(out.at(x, 8)[0], 1.0f, 0.02f) << "x " << x;
}

// A box of two colours (1 left, 4 right of its middle) moving 2 px a frame, whose colours
// drift from where its vectors carry them in the far frames (as a step of a chain astray on a
// tumbling object lands): the border is 2.5 px left of where the vectors put it three and more
// frames behind frame 6, 4 px left three and more ahead. Pixel 19's chains land on the border
// behind (a block of both colours) and on the right colour ahead.
Scene boxWithDriftingColours() {
  Scene scene;
  scene.trace = [](int frame, double x, double, double& movesX) {
    const double left = 4.0 + 2.0 * frame;
    if (x < left || x >= left + 12.0) return Hit{0.2f, 10.0};
    movesX = 2.0 * 1.0 / kFocal;  // 2 px at depth 1
    const double drift = frame <= 3 ? -2.5 : (frame >= 9 ? -4.0 : 0.0);
    return Hit{x < left + 6.0 + drift ? 1.0f : 4.0f, 1.0};
  };
  return scene;
}

// The block of two colours behind is rejected by the colour test, but its spread, pooled as
// the pixel's noise, loosened the test for the frames ahead until their wrong colour passed:
// specks of the other colour inside a tumbling cube's squares at 1080p (docs/TUNING.md, "The
// chains' spread").
TEST_F(WindowTest, AChainsBlockAcrossAnEdgeDoesNotLetTheFartherFramesWrongColourIn) {
  const Scene scene = boxWithDriftingColours();
  const int frame = 6;  // the box covers x 16..28, its colours meet at 22
  const Image out = resolve(scene, frame, windowOptions(4));
  for (int y = 2; y < kHeight - 2; ++y) EXPECT_NEAR(out.at(19, y)[0], 1.0f, 0.02f) << "y " << y;
}

// The window's first frame has no previous frame to check its vectors against: the camera
// carries each sample into the next frame instead. The box's trailing 2 px there are backdrop
// in the next frame, which cannot vouch for them; taken for static, they were carried to t
// where the box had long left (a ghost of its edge, which the colour test hides only where
// the object looks like what it uncovers: Cryptomatte and data passes showed it). With the
// colour test off, only the classification keeps them out.
TEST_F(WindowTest, TheTrailingEdgeInTheWindowsFirstFrameIsNotTakenForStatic) {
  const Scene scene = movingBox();
  const int frame = 8;  // frame 2 (the window's first) has the box at x 8..16
  ResolveOptions options = windowOptions(6);
  options.window.colourTolerance = 0.0f;
  const Image out = resolve(scene, frame, options);
  for (int x : {8, 9, 12, 14}) EXPECT_NEAR(out.at(x, 8)[0], 0.2f, 0.02f) << "x " << x;
}

// A shadow edge sweeping right 2 px a frame over a still, lit plane: shading changes where
// nothing moves. Pixels lit in this frame were in shadow in half the window.
Scene sweepingShadow() {
  Scene scene;
  scene.trace = [](int frame, double x, double, double&) {
    return Hit{x < 6.0 + 2.0 * frame ? 0.1f : 1.0f, 5.0};
  };
  return scene;
}

TEST_F(WindowTest, AMovingShadowIsNotSmeared) {
  const Scene scene = sweepingShadow();
  const int frame = 8;  // the edge at x = 22
  // The default window (K and colour tolerance as chosen on the real lit scene).
  ResolveOptions options = windowOptions(ResolveOptions{}.window.radius);
  const Image out = resolve(scene, frame, options);
  for (int x : {24, 26, 28}) EXPECT_GT(out.at(x, 8)[0], 0.9f) << "x " << x;
  for (int x : {15, 17, 19}) EXPECT_LT(out.at(x, 8)[0], 0.2f) << "x " << x;
  // Without the colour test, the region test and the tile test the shadow's past and future
  // smear over the lit pixels (and without settling, which ends a flat pixel's window at its
  // nearest frames, before the ones that would smear it).
  options.window.colourTolerance = 0.0f;
  options.window.regionTolerance = 0.0f;
  options.window.nearRadius = 0;
  options.window.settle = 0.0f;
  const Image smeared = resolve(scene, frame, options);
  EXPECT_LT(smeared.at(26, 8)[0], out.at(26, 8)[0] - 0.1f);
}

// A smooth pattern (1 to 3, a period of 7 px) on a still plane whose right 8 px (the second
// tile of 32) turn 30% brighter from frame 12 on, as under a light coming up: less than each
// pixel's own colour test can tell from the pattern's spread, plain when pooled over a tile.
Scene patternBrighteningOnTheRight() {
  Scene scene;
  scene.trace = [](int frame, double x, double, double&) {
    const double pattern = 2.0 + std::sin(0.9 * x);
    return Hit{float(pattern * (x >= 32.0 && frame >= 12 ? 1.3 : 1.0)), 5.0};
  };
  return scene;
}

double meanError(const Scene& scene, const Image& out, int frame, int x0, int x1) {
  double sum = 0.0;
  int count = 0;
  for (int y = 2; y < kHeight - 2; ++y) {
    for (int x = x0; x < x1; ++x, ++count) {
      sum += std::fabs(out.at(x, y)[0] - truth(scene, frame, x, y));
    }
  }
  return sum / count;
}

TEST_F(WindowTest, TheTileTestEndsTheWindowWhereShadingChangesAndKeepsItWhereItHolds) {
  const Scene scene = patternBrighteningOnTheRight();
  const int frame = 8;  // frames 12..14 of its window (K 6) are brighter on the right
  ResolveOptions options = windowOptions(6);
  options.window.nearRadius = 2;
  options.window.movingRadius = 0;
  const Image tiles = resolve(scene, frame, options);
  options.window.nearRadius = 0;
  const Image whole = resolve(scene, frame, options);
  // The right tile stops short of the brighter frames (its reach filtered with the left
  // tile's towards x = 16); the whole window lets them in.
  EXPECT_LT(meanError(scene, tiles, frame, 36, 40), 0.6 * meanError(scene, whole, frame, 36, 40));
  // The left tile, whose frames all agree, reaches the whole window: where its reach is its
  // own (x <= 16), the same bits.
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < 16; ++x) {
      ASSERT_EQ(tiles.at(x, y)[0], whole.at(x, y)[0]) << x << "," << y;
    }
  }
}

// The longest window (K 24: 48 sources, the last twelve of whose tile statistics fill the fourth
// texel): frames 19 and more ahead of t brighten on the right, as a light switched on late in
// a long static shot. The tile test stops the right tile short of them and lets the left tile
// reach every frame.
TEST_F(WindowTest, TheLongestWindowsFarFramesAreTestedByTile) {
  Scene scene;
  const int frame = 8;
  scene.trace = [](int f, double x, double, double&) {
    const double pattern = 2.0 + std::sin(0.9 * x);
    return Hit{float(pattern * (x >= 32.0 && f >= frame + 19 ? 1.3 : 1.0)), 5.0};
  };
  ResolveOptions options = windowOptions(kMaxWindowRadius);
  options.window.movingRadius = 0;
  options.window.falloff = 0.0f;  // every frame alike: the far ones count as much as the near
  options.window.nearRadius = 2;
  const Image tiles = resolve(scene, frame, options);
  options.window.nearRadius = 0;
  const Image whole = resolve(scene, frame, options);
  const double tilesError = meanError(scene, tiles, frame, 36, 40);
  const double wholeError = meanError(scene, whole, frame, 36, 40);
  EXPECT_LT(tilesError, 0.6 * wholeError) << tilesError << " against " << wholeError;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < 16; ++x) {
      ASSERT_EQ(tiles.at(x, y)[0], whole.at(x, y)[0]) << x << "," << y;
    }
  }
}

// Stripes 1.6 px wide every 3.7 px (edges at every sub-pixel phase) on a still plane, the camera
// panning 0.41 px a frame: the carried samples land at scattered offsets from the pixel centres.
Scene stripesUnderAPan() {
  Scene scene;
  scene.cameraX = [](int frame) { return 0.41 * frame * 5.0 / kFocal; };  // world X at depth 5
  scene.trace = [](int frame, double x, double, double&) {
    const double worldX = worldXAt(x, 5.0, 0.41 * frame * 5.0 / kFocal);
    const double phase = worldX * kFocal / 5.0 / 3.7;
    return Hit{phase - std::floor(phase) < 1.6 / 3.7 ? 1.0f : 0.0f, 5.0};
  };
  return scene;
}

// The quadrants' means (--window-strata) against the plain mean: where samples land unevenly
// in a pixel, the plain mean weighs each side of an edge by the samples that happened to land
// there; the stratified one comes closer to the pixel's coverage.
TEST_F(WindowTest, StrataBringEdgePixelsCloserToTheirCoverage) {
  const Scene scene = stripesUnderAPan();
  double strataError = 0.0, plainError = 0.0;
  int edges = 0;
  for (int frame = 16; frame <= 24; frame += 4) {
    ResolveOptions options = windowOptions(8);
    ASSERT_TRUE(options.window.strata);  // the default
    const Image strata = resolve(scene, frame, options);
    options.window.strata = false;
    const Image plain = resolve(scene, frame, options);
    for (int x = 4; x < kWidth - 4; ++x) {
      const float expected = truth(scene, frame, x, 8);
      if (expected < 0.02f || expected > 0.98f) continue;  // edge pixels only
      ++edges;
      strataError += std::fabs(strata.at(x, 8)[0] - expected);
      plainError += std::fabs(plain.at(x, 8)[0] - expected);
    }
  }
  ASSERT_GT(edges, 30);
  EXPECT_LT(strataError, 0.9 * plainError) << strataError / edges << " against "
                                            << plainError / edges;
}

// A still floor under one-sample noise (each sample its own, +-40 %) with a 12 px patch 35 %
// darker moving `speed` px a frame (over x 20..32 at frame 8), as a contact shadow moves with its
// object: a frame's samples in the patch differ from the other frames' by less than one
// sample's noise, so the per-pixel colour test lets the unshadowed frames in; over a 5x5
// region the difference is plain.
Scene shadowOnANoisyFloor(double speed = 1.5) {
  Scene scene;
  scene.trace = [speed](int frame, double x, double y, double&) {
    const std::uint32_t seed = std::uint32_t(frame) * 73856093u ^
                               std::uint32_t(std::floor(x * 64.0)) * 19349663u ^
                               std::uint32_t(std::floor(y * 64.0)) * 83492791u;
    const double noise = double((seed * 2654435761u) >> 8) / double(1u << 24);  // 0..1
    const double patch = 20.0 + speed * (frame - 8);
    const bool shadowed = x >= patch && x < patch + 12.0 && y >= 2.0 && y < 14.0;
    return Hit{float(0.5 * (0.6 + 0.8 * noise) * (shadowed ? 0.65 : 1.0)), 5.0};
  };
  return scene;
}

// The mean of `image`'s first channel over columns [x0, x1) and rows [y0, y1).
double meanOver(const Image& image, int x0, int x1, int y0, int y1) {
  double sum = 0.0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) sum += image.at(x, y)[0];
  }
  return sum / double((x1 - x0) * (y1 - y0));
}

constexpr double kShadowedFloor = 0.5 * 0.65;  // the noisy floor's mean, 35 % darker

PatchMeans WindowTest::patchMeans(const Scene& scene, int frame, ResolveOptions options,
                                  const std::function<void(ResolveOptions&)>& change, int x0,
                                  int x1, int y0, int y1) {
  const double asGiven = meanOver(resolve(scene, frame, options), x0, x1, y0, y1);
  change(options);
  return {asGiven, meanOver(resolve(scene, frame, options), x0, x1, y0, y1)};
}

// The patch as given is nearer the shadowed floor's mean than `share` of the changed one's
// brightening over it.
void expectNearerTheShadow(PatchMeans means, double share) {
  EXPECT_LT(std::fabs(means.asGiven - kShadowedFloor), share * (means.changed - kShadowedFloor))
      << means.asGiven << " and " << means.changed << " against " << kShadowedFloor;
}

// The region test (--window-region-tolerance) keeps the patch where the pixel's own test
// cannot.
TEST_F(WindowTest, TheRegionTestKeepsAShadowThatOneSamplesNoiseHides) {
  const Scene scene = shadowOnANoisyFloor();
  const int frame = 8;  // the patch over x 20..32, y 2..14
  const ResolveOptions options = windowOptions(ResolveOptions{}.window.radius);
  ASSERT_GT(options.window.regionTolerance, 0.0f);  // the default
  // Inside the patch, the mean brightening over the shadowed floor's own mean (the unshadowed
  // frames' samples lighten it; the noise, left less averaged by the region test, evens out).
  const auto untested = [](ResolveOptions& o) { o.window.regionTolerance = 0.0f; };
  expectNearerTheShadow(patchMeans(scene, frame, options, untested, 23, 29, 5, 11), 0.5);
}

// shadowOnANoisyFloor with the block that casts the patch standing in front of it, nearer
// (depth 4) and moving with it: the patch is a contact shadow.
Scene contactShadowOnANoisyFloor(double speed = 1.5) {
  Scene scene = shadowOnANoisyFloor(speed);
  const auto floor = scene.trace;
  scene.trace = [floor, speed](int frame, double x, double y, double& movesX) {
    const double block = 16.0 + speed * (frame - 8);  // 4 px wide, just left of the patch
    if (x >= block && x < block + 4.0 && y >= 2.0 && y < 14.0) {
      movesX = speed * 4.0 / kFocal;  // `speed` px a frame at depth 4
      return Hit{0.9f, 4.0};
    }
    return floor(frame, x, y, movesX);
  };
  return scene;
}

// Within 16 px of a moving sample the region test takes --window-region-near-moving standard
// errors (default 2) instead of --window-region-tolerance's 3: the frames whose means
// straddle the moving shadow's edge are told apart there as well.
TEST_F(WindowTest, TheRegionTestIsStricterBesideAMovingObject) {
  const Scene scene = contactShadowOnANoisyFloor();
  const int frame = 8;  // the block over x 16..20, the patch over x 20..32, y 2..14
  const ResolveOptions options = windowOptions(ResolveOptions{}.window.radius);
  ASSERT_LT(options.window.regionToleranceNearMoving, options.window.regionTolerance);
  // The mean brightening over the shadowed floor's own mean across the whole patch, its
  // edges included (measured: 0.015 with the default, 0.035 with 3).
  const auto loose = [](ResolveOptions& o) {
    o.window.regionToleranceNearMoving = o.window.regionTolerance;
  };
  expectNearerTheShadow(patchMeans(scene, frame, options, loose, 21, 31, 3, 13), 0.6);
}

// The same contact shadow moving 8 px a frame, as a 1080p render's does: where the patch is at
// t, t-1 and t+1 saw mostly lit floor. Near a moving sample the region test weighs t+-1 by its
// stricter tolerance (docs/TUNING.md, "Contact shadows at 1080p"), so with them alone (--window
// 1) the patch stays dark; with the near-moving test loosened to nothing, it is lit (measured:
// the patch's mean 0.326 and 0.380, the shadowed floor's 0.325; 0.380 both when t+-1 went
// untested).
TEST_F(WindowTest, NearAMovingObjectTheNextFramesAreRegionTestedToo) {
  const Scene scene = contactShadowOnANoisyFloor(8.0);
  const int frame = 8;  // the block over x 16..20, the patch over x 20..32, y 2..14
  const auto loose = [](ResolveOptions& o) { o.window.regionToleranceNearMoving = 1000.0f; };
  expectNearerTheShadow(patchMeans(scene, frame, windowOptions(1), loose, 22, 30, 4, 12),
                        0.5);
}

// A shadow sweeping 8 px a frame with nothing moving near it (a moving light's, at 1080p): t+-1
// are region-tested as every other frame is (docs/TUNING.md, "The region test for t+-1"), so
// with them alone (--window 1) the patch stays dark; with the region test off, t+-1's lit floor
// lightens it (measured: the patch's mean 0.342 and 0.399, the shadowed floor's 0.325; 0.399
// both when t+-1 went untested).
TEST_F(WindowTest, TheNextFramesAreRegionTestedAwayFromMovingObjectsToo) {
  const Scene scene = shadowOnANoisyFloor(8.0);
  const int frame = 8;  // the patch over x 20..32, y 2..14
  const ResolveOptions options = windowOptions(1);
  ASSERT_GT(options.window.regionTolerance, 0.0f);  // the default
  const auto untested = [](ResolveOptions& o) { o.window.regionTolerance = 0.0f; };
  expectNearerTheShadow(patchMeans(scene, frame, options, untested, 22, 30, 4, 12), 0.5);
}

// A faint shadow (3 % darker) sweeping 8 px a frame over a floor that brightens smoothly to the
// right, without noise. The region test fits a plane to each 6x6 (docs/TUNING.md, "A plane for
// the region test"): the ramp is no noise, so t+-1's unshadowed floor is told apart from the
// patch, and with them alone (--window 1) the patch keeps its value; with the region test off
// they lighten it (measured: the patch's mean error 0.0005 and 0.0108; 0.0095 with the test of
// 6x6 means, which took the ramp's variance as its noise).
TEST_F(WindowTest, TheRegionTestTellsAFaintShadowFromAGradient) {
  Scene scene;
  scene.trace = [](int frame, double x, double y, double&) {
    const double patch = 20.0 + 8.0 * (frame - 8);
    const bool shadowed = x >= patch && x < patch + 12.0 && y >= 2.0 && y < 14.0;
    return Hit{float((0.2 + 0.02 * x) * (shadowed ? 0.97 : 1.0)), 5.0};
  };
  const int frame = 8;  // the patch over x 20..32, y 2..14
  const auto untested = [](ResolveOptions& o) { o.window.regionTolerance = 0.0f; };
  const PatchMeans means = patchMeans(scene, frame, windowOptions(1), untested, 22, 30, 4, 12);
  double truthMean = 0.0;
  for (int y = 4; y < 12; ++y) {
    for (int x = 22; x < 30; ++x) truthMean += truth(scene, frame, x, y) / 64.0;
  }
  const double testedError = std::fabs(means.asGiven - truthMean);
  const double untestedError = std::fabs(means.changed - truthMean);
  EXPECT_LT(testedError, 0.5 * untestedError) << testedError << " and " << untestedError;
}

// A box moving 4 px a frame over a still backdrop (lit: 1), with a shadow 5 px wide beside it
// that moves with it, rendered as a noisy render samples it: each sample 0 or 0.4 at random
// (mean 0.2). The shadow's other frames saw the lit backdrop there and are left out.
Scene boxWithNoisyShadow() {
  Scene scene;
  scene.trace = [](int frame, double x, double y, double& movesX) {
    const double left = -8.0 + 4.0 * frame;
    if (x >= left && x < left + 8.0) {
      movesX = 4.0 * 1.0 / kFocal;  // 4 px at depth 1
      return Hit{0.5f, 1.0};
    }
    if (x < left + 8.0 || x >= left + 13.0) return Hit{1.0f, 10.0};
    std::uint32_t h = std::uint32_t(std::floor(x * 1024.0)) * 73856093u ^
                      std::uint32_t(std::floor(y * 1024.0)) * 19349663u ^
                      std::uint32_t(frame + 100) * 83492791u;
    h ^= h >> 13;
    h *= 0x5bd1e995u;
    h ^= h >> 15;
    return Hit{(h & 1u) != 0u ? 0.4f : 0.0f, 10.0};
  };
  return scene;
}

// Only t's own samples can tell the shadow: the fallback takes more of them, so less of their
// noise is left (docs/TUNING.md, "A contact shadow's own samples").
TEST_F(WindowTest, AShadowMovingWithItsObjectTakesMoreOfItsOwnSamples) {
  const Scene scene = boxWithNoisyShadow();
  const int frame = 6;  // the box covers x 16..24, its shadow 24..29
  ResolveOptions options = windowOptions(4);
  ASSERT_GT(options.window.ownFallback, 0.0f);  // the default
  const auto meanError = [&](const Image& out) {
    double sum = 0.0;
    int count = 0;
    for (int y = 2; y < kHeight - 2; ++y) {
      for (int x = 26; x <= 27; ++x, ++count) sum += std::fabs(out.at(x, y)[0] - 0.2);
    }
    return sum / count;
  };
  const double withFallback = meanError(resolve(scene, frame, options));
  options.window.ownFallback = 0.0f;
  const double without = meanError(resolve(scene, frame, options));
  EXPECT_LT(withFallback, 0.6 * without) << withFallback << " against " << without;
  // And the lit frames stay out: the shadow is not brightened toward 1.
  EXPECT_LT(withFallback, 0.1);
}

// Away from moving samples the looser test holds: on the noisy floor without its block, the
// near-moving tolerance changes no bit.
TEST_F(WindowTest, TheNearMovingToleranceLeavesAStillShotAlone) {
  const Scene scene = shadowOnANoisyFloor();
  ResolveOptions options = windowOptions(ResolveOptions{}.window.radius);
  options.window.regionToleranceNearMoving = 0.5f;
  const Image strict = resolve(scene, 8, options);
  options.window.regionToleranceNearMoving = options.window.regionTolerance;
  const Image loose = resolve(scene, 8, options);
  ASSERT_EQ(strict.pixels.size(), loose.pixels.size());
  EXPECT_EQ(std::memcmp(strict.pixels.data(), loose.pixels.data(),
                        strict.pixels.size() * sizeof(float)),
            0);
}

// Bands 12 px wide, 1.0 and 0.25, under a pan of 0.37 px a frame: most pixels' 3x3 is flat.
Scene wideBandsUnderAPan() {
  Scene scene;
  scene.cameraX = [](int frame) { return 0.37 * frame * 5.0 / kFocal; };
  scene.trace = [](int frame, double x, double, double&) {
    const double phase = worldXAt(x, 5.0, 0.37 * frame * 5.0 / kFocal) * kFocal / 5.0 / 24.0;
    return Hit{phase - std::floor(phase) < 0.5 ? 1.0f : 0.25f, 5.0};
  };
  return scene;
}

// --window-settle: a pixel whose own 3x3 and nearest frames agree stops gathering (far fewer
// candidate samples) and keeps its value; an edge pixel gathers its whole window as before.
TEST_F(WindowTest, AFlatPixelStopsGatheringOnceItsNearestFramesAgree) {
  const Scene scene = wideBandsUnderAPan();
  ResolveOptions options = windowOptions(8);
  ASSERT_GT(options.window.settle, 0.0f);  // the default
  auto resolveWithDebug = [&](const ResolveOptions& o, Image& debug) {
    WindowResolver resolver(*context_, o);
    resolver.setDebugOutput(true);
    Image out = resolveWith(resolver, scene, 20, o.window.radius);
    debug = resolver.lastDebug();
    return out;
  };
  Image settledDebug, wholeDebug;
  const Image settled = resolveWithDebug(options, settledDebug);
  options.window.settle = 0.0f;
  const Image whole = resolveWithDebug(options, wholeDebug);
  int flat = 0, edges = 0;
  for (int y = 3; y < kHeight - 3; ++y) {
    for (int x = 3; x < kWidth - 3; ++x) {
      const float expected = truth(scene, 20, x, y);
      const bool flatAround = truth(scene, 20, x - 2, y) == expected &&
                              truth(scene, 20, x + 2, y) == expected &&
                              (expected == 1.0f || expected == 0.25f);
      const float candidates = settledDebug.at(x, y)[2], wholeCandidates = wholeDebug.at(x, y)[2];
      if (flatAround) {
        ++flat;
        EXPECT_NEAR(settled.at(x, y)[0], whole.at(x, y)[0], 1e-5f) << x << "," << y;
        EXPECT_LT(candidates, 0.5f * wholeCandidates) << x << "," << y;
      } else if (expected > 0.26f && expected < 0.99f) {
        ++edges;
        EXPECT_EQ(settled.at(x, y)[0], whole.at(x, y)[0]) << x << "," << y;
        EXPECT_EQ(candidates, wholeCandidates) << x << "," << y;
      }
    }
  }
  EXPECT_GT(flat, 100);
  EXPECT_GT(edges, 20);
}

// Each frame depends on its window alone: a resolver that has seen the whole shot and one
// that holds just the window give the same bits.
TEST_F(WindowTest, AFrameDependsOnItsWindowAlone) {
  const Scene scene = wireBeforeBackdrop();
  const ResolveOptions options = windowOptions(3);
  WindowResolver running(*context_, options);
  Image fromRunning;
  for (int frame = 4; frame <= 12; ++frame) {
    for (int f = frame - 8; f < frame - 3; ++f) running.dropFrame(f);
    const Image out = resolveWith(running, scene, frame, 3);
    if (frame == 9) fromRunning = out;
  }
  WindowResolver fresh(*context_, options);
  const Image alone = resolveWith(fresh, scene, 9, 3);
  ASSERT_EQ(alone.pixels.size(), fromRunning.pixels.size());
  EXPECT_EQ(std::memcmp(alone.pixels.data(), fromRunning.pixels.data(),
                        alone.pixels.size() * sizeof(float)),
            0);
}

// With passes a run's peak memory is its bar: while a resolver has them, the frame buffer pool
// keeps nothing, whichever face drives the resolver; without, and once it is gone, it keeps.
TEST_F(WindowTest, TheFrameBufferPoolKeepsNothingWhileAResolverHasPasses) {
  constexpr std::size_t kFrameBytes = std::size_t(8) << 20;
  const auto keepsAFreedBuffer = [] {
    releaseFrameBuffers();
    giveBackFrameBuffer(takeFrameBuffer(kFrameBytes), kFrameBytes);
    return keptFrameBufferBytes() == kFrameBytes;
  };
  WindowResolver plain(*context_, windowOptions(1));
  EXPECT_TRUE(keepsAFreedBuffer());
  {
    WindowResolver withPasses(*context_, windowOptions(1));
    withPasses.setPasses({true, false}, 1);
    EXPECT_FALSE(keepsAFreedBuffer());
    withPasses.setPasses({}, 0);
    EXPECT_TRUE(keepsAFreedBuffer());
    withPasses.setPasses({false}, 0);
    EXPECT_FALSE(keepsAFreedBuffer());
  }
  EXPECT_TRUE(keepsAFreedBuffer());
  releaseFrameBuffers();
}

// A pass group whose type is not its ring's (a face that packed by another plan) is refused
// with a message naming the group and the frame, and the ring keeps nothing of it.
TEST_F(WindowTest, APassGroupOfTheOtherTypeIsRefused) {
  const Scene scene = staticEdge();
  const Frame data = render(scene, 3);
  WindowResolver resolver(*context_, windowOptions(1));
  resolver.setPasses({true}, 0);  // a half group: the float colour is not one
  ResolveInput input;
  input.color = &data.color;
  input.passGroups = {&data.color};
  input.depth = &data.depth;
  input.motion = &data.motion;
  input.jitter = data.jitter;
  input.window = {0, 0, kWidth, kHeight};
  input.ndc = NdcConvention::ZeroOneYDown;
  try {
    resolver.addFrame(3, input);
    FAIL() << "a float group went into a half ring";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("pass group 0 is float where its ring is half"),
              std::string::npos)
        << e.what();
    EXPECT_EQ(e.context().frame, std::optional<int>(3));
  }
  EXPECT_FALSE(resolver.hasFrame(3));
}

TEST_F(WindowTest, AFullRingIsAnError) {
  const Scene scene = staticEdge();
  WindowResolver resolver(*context_, windowOptions(1));
  EXPECT_THROW(resolveWith(resolver, scene, 5, 2), Error);
}

}  // namespace
}  // namespace taa
