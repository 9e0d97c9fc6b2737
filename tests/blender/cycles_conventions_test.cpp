// Blender Cycles' conventions, checked on files Blender writes (DESIGN.md section 3, the facts
// samples/blender/taa_scenes/render.py relies on). The scene's surfaces emit their own world
// position, so each 1-spp sample says where it landed: projecting that point with the frame's
// camera from the sidecar gives the sample's raster position (the jitter), and projecting it
// with the previous frame's camera gives the motion a static surface must have. A Blender
// upgrade that changes any of these fails here.
#include <unistd.h>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "io/aov_layout.h"
#include "io/camera_sidecar.h"
#include "io/frame_reader.h"
#include "resolve/camera.h"
#include "resolve/jitter.h"
#include "blender_tmpdir.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 64, kHeight = 48, kFirst = 1, kLast = 3;

// Renders the conventions scene once per test process (float colour: positions need it),
// into a folder of its own: CTest runs each test in a process of its own, in parallel.
const std::string& renderedScene() {
  static const std::string dir = [] {
    const std::string out =
        std::string(TAA_TEST_TMPDIR) + "/cycles_conventions_" + std::to_string(getpid());
    fs::remove_all(out);
    fs::create_directories(out);
    test::keepBlendersTemporaryFilesInTheTestFolder();
    const std::string command =
        "blender -b --factory-startup -noaudio -P '" + std::string(TAA_BLENDER_SCRIPT) +
        "' -- --scene cycles_conventions --out '" + out + "' --size 64x48 --frames 1-3 "
        "--products camera,input --input-depth float > '" + out + "/blender.log' 2>&1";
    if (std::system(command.c_str()) != 0) {
      ADD_FAILURE() << "Blender failed (Debian's blender is installed by "
                       "scripts/install-deps.sh); see " << out << "/blender.log";
    }
    return out;
  }();
  return dir;
}

struct Frame {
  io::FrameData data;
  const Image* color() const { return data.color.floats(); }
};

Frame readRendered(int frame, const io::CameraSidecar& sidecar) {
  const io::AovLayout layout = io::cyclesLayout(renderedScene() + "/input.####.exr");
  return {io::readFrame(layout, frame, {NdcConvention::ZeroOneYDown, &sidecar})};
}

// Raster position (pixels, y down) of a world point in a frame's camera.
glm::dvec2 rasterOf(const FrameCamera& camera, NdcConvention ndc, const glm::dvec3& world) {
  const glm::dmat4 toRaster = glm::inverse(ndcFromRaster({0, 0, kWidth, kHeight}, ndc));
  const glm::dvec4 clip = camera.worldToNdc * glm::dvec4(world, 1.0);
  const glm::dvec4 raster = toRaster * (clip / clip.w);
  return {raster.x, raster.y};
}

glm::dvec3 worldPointAt(const Image& color, int x, int y) {
  const float* p = color.at(x, y);
  return {p[0], p[1], p[2]};
}

class CyclesConventions : public ::testing::Test {
 protected:
  void SetUp() override {
    sidecar_ = io::CameraSidecar::load(renderedScene() + "/camera.json");
  }
  io::CameraSidecar sidecar_;
};

TEST_F(CyclesConventions, TheSampleLandsAtTheHaltonJitterTheSidecarStates) {
  for (int f = kFirst; f <= kLast; ++f) {
    const Frame frame = readRendered(f, sidecar_);
    ASSERT_NE(frame.color(), nullptr) << "the conventions scene is rendered as float";
    ASSERT_TRUE(frame.data.camera.has_value());
    const glm::vec2 halton = frameJitter(f, JitterOptions{});
    EXPECT_NEAR(sidecar_.jitter(f).x, halton.x, 1e-6);
    EXPECT_NEAR(sidecar_.jitter(f).y, halton.y, 1e-6);
    int hits = 0;
    double worst = 0.0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        if (std::isinf(frame.data.depth.at(x, y)[0])) continue;
        const glm::dvec2 sample = rasterOf(*frame.data.camera, frame.data.ndc,
                                           worldPointAt(*frame.color(), x, y));
        const glm::dvec2 expected(x + 0.5 + halton.x, y + 0.5 + halton.y);
        worst = std::max(worst, glm::length(sample - expected));
        ++hits;
      }
    }
    EXPECT_GT(hits, kWidth * kHeight / 2) << "frame " << f;
    EXPECT_LT(worst, 0.01) << "frame " << f << ": sample off its jitter by " << worst << " px";
  }
}

TEST_F(CyclesConventions, DepthIsPlanarAndNoHitIsInfinite) {
  const Frame frame = readRendered(2, sidecar_);
  int hits = 0, misses = 0;
  for (int y = 0; y < kHeight; ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float depth = frame.data.depth.at(x, y)[0];
      if (std::isinf(depth)) {
        ++misses;
        continue;
      }
      const glm::dvec4 camera = frame.data.camera->worldToCamera *
                                glm::dvec4(worldPointAt(*frame.color(), x, y), 1.0);
      EXPECT_NEAR(depth, camera.z, 1e-4 * camera.z) << "pixel " << x << "," << y;
      ++hits;
    }
  }
  EXPECT_GT(hits, 0);
  EXPECT_GT(misses, 0) << "the scene shows empty background too";
}

TEST_F(CyclesConventions, VectorsAgreeWithCameraReprojectionOnStaticGeometry) {
  for (int f = kFirst + 1; f <= kLast; ++f) {
    const Frame frame = readRendered(f, sidecar_);
    const FrameCamera& previous = sidecar_.camera(f - 1);
    const glm::vec2 jitter = frameJitter(f, JitterOptions{});
    double worst = 0.0, largest = 0.0;
    int skyWithCameraMotion = 0;
    for (int y = 0; y < kHeight; ++y) {
      for (int x = 0; x < kWidth; ++x) {
        const float depth = frame.data.depth.at(x, y)[0];
        const glm::dvec2 vector(frame.data.motion.at(x, y)[0], frame.data.motion.at(x, y)[1]);
        const glm::dvec2 sample(x + 0.5 + jitter.x, y + 0.5 + jitter.y);
        const glm::dvec2 camera = cameraMotion(*frame.data.camera, previous,
                                               {0, 0, kWidth, kHeight}, frame.data.ndc, sample,
                                               depth);
        if (std::isinf(depth)) {
          // Cycles writes no motion where nothing is hit, even when the camera turns: camera
          // reprojection has to fill the sky (--camera-motion fill).
          EXPECT_EQ(vector.x, 0.0);
          EXPECT_EQ(vector.y, 0.0);
          skyWithCameraMotion += glm::length(camera) > 0.5 ? 1 : 0;
          continue;
        }
        worst = std::max(worst, glm::length(vector - camera));
        largest = std::max(largest, glm::length(camera));
      }
    }
    EXPECT_GT(largest, 2.0) << "frame " << f << ": the camera moves";
    EXPECT_GT(skyWithCameraMotion, 0) << "frame " << f << ": the camera turns";
    EXPECT_LT(worst, 0.01) << "frame " << f << ": vectors off the camera's motion by " << worst
                           << " px";
  }
}

}  // namespace
}  // namespace taa
