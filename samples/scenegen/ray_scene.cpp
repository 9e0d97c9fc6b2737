#include "scenegen/ray_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include "scenegen/parallel_for.h"
#include "taa/error.h"

namespace taa::scenes {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kRefinePerAxis = 8;         // sub-samples per axis in a refined truth cell
constexpr float kRefineThreshold = 0.05f;  // linear difference between cells that refines them

// A well-mixed 32-bit integer hash, so every pixel and cell gets its own jitter.
std::uint32_t hash32(std::uint32_t x) {
  x ^= x >> 16;
  x *= 0x21f0aaadu;
  x ^= x >> 15;
  x *= 0xd35a2d97u;
  x ^= x >> 15;
  return x;
}

// The hash every sample of pixel (i, j) under `seed` starts from.
std::uint32_t pixelHash(std::uint32_t seed, int i, int j) {
  return hash32(seed * 0x9e3779b9u ^ hash32(std::uint32_t(i) * 73856093u ^
                                            std::uint32_t(j) * 19349663u));
}

// Two uniform numbers in [0, 1) (16 bits each) for sample k of a pixel.
glm::dvec2 unitPair(std::uint32_t pixel, std::uint32_t k) {
  const std::uint32_t bits = hash32(pixel ^ (k * 0x85ebca6bu));
  return {((bits & 0xffffu) + 0.5) * (1.0 / 65536.0), ((bits >> 16) + 0.5) * (1.0 / 65536.0)};
}

bool onRaster(glm::dvec2 p, int width, int height) {
  return p.x >= 0.0 && p.y >= 0.0 && p.x < width && p.y < height;
}

}  // namespace

RayScene::RayScene(std::string name, int width, int height, RaySceneSpec spec)
    : Scene(std::move(name), width, height), spec_(std::move(spec)) {
  if (width <= 0 || height <= 0) throw Error("scene size must be positive: " + this->name());
  if (!spec_.camera) throw Error("3D scene without a camera: " + this->name());
  for (const SceneObject& object : spec_.objects) {
    if (!object.shade) throw Error("object without a shader in scene " + this->name());
  }
}

Camera RayScene::camera(int frame) const { return Camera(spec_.camera(frame), width(), height()); }

RayScene::FrameState RayScene::state(int frame) const {
  FrameState s{frame, camera(frame), {}};
  const glm::dvec3 eye = s.camera.position();
  for (const SceneObject& object : spec_.objects) {
    const glm::dmat4 toWorld = object.objectToWorld ? object.objectToWorld(frame) : glm::dmat4(1.0);
    const glm::dmat4 toLocal = glm::inverse(toWorld);
    // The bounding sphere's world radius: scale by the longest axis of the transform.
    const glm::dmat3 linear(toWorld);
    const double scale = std::max({glm::length(linear[0]), glm::length(linear[1]),
                                   glm::length(linear[2])});
    const double radius = boundingRadius(object.shape) * scale;
    s.objects.push_back({&object, toWorld, toLocal, glm::dmat3(toLocal),
                         glm::transpose(glm::dmat3(toLocal)),
                         glm::dvec3(toLocal * glm::dvec4(eye, 1.0)),
                         glm::dvec3(toWorld[3]) - eye, radius * radius});
  }
  return s;
}

bool RayScene::trace(const FrameState& state, const Ray& ray, Trace* out) {
  double nearest = kInf;
  const double dd = glm::dot(ray.direction, ray.direction);
  for (std::size_t k = 0; k < state.objects.size(); ++k) {
    const PlacedObject& placed = state.objects[k];
    if (placed.radiusSquared < kInf) {
      // Skip objects whose bounding sphere the ray misses.
      const double along = glm::dot(placed.eyeToCentre, ray.direction);
      const double miss = glm::dot(placed.eyeToCentre, placed.eyeToCentre) - along * along / dd;
      if (miss > placed.radiusSquared) continue;
    }
    const glm::dvec3 d = placed.localDirection * ray.direction;
    LocalHit hit;
    if (!intersect(placed.object->shape, placed.localEye, d, 1e-6, nearest, &hit)) continue;
    if (placed.object->cutout && !placed.object->cutout(hit.point)) continue;
    nearest = hit.t;
    out->object = int(k);
    out->hit = hit;
  }
  return nearest < kInf;
}

glm::vec3 RayScene::shade(const FrameState& state, const Ray& ray, const Trace& trace) const {
  const PlacedObject& placed = state.objects[trace.object];
  SurfacePoint point;
  point.local = trace.hit.point;
  point.localNormal = trace.hit.normal;
  point.world = ray.origin + trace.hit.t * ray.direction;
  point.worldNormal = glm::normalize(placed.normalToWorld * trace.hit.normal);
  if (glm::dot(point.worldNormal, ray.direction) > 0.0) point.worldNormal = -point.worldNormal;
  point.cameraPosition = ray.origin;
  return placed.object->shade(point);
}

glm::vec3 RayScene::radiance(const FrameState& state, glm::dvec2 raster) const {
  const Ray ray = state.camera.ray(raster);
  Trace hit;
  if (trace(state, ray, &hit)) return shade(state, ray, hit);
  return spec_.sky ? spec_.sky(glm::normalize(ray.direction)) : glm::vec3(0.0f);
}

RayScene::View RayScene::view(int frame, glm::dvec2 raster) const {
  const FrameState s = state(frame);
  const Ray ray = s.camera.ray(raster);
  View result;
  Trace hit;
  if (trace(s, ray, &hit)) {
    result.object = hit.object;
    result.depth = hit.hit.t;
    result.local = hit.hit.point;
    result.rgb = shade(s, ray, hit);
  } else {
    result.depth = kInf;
    result.rgb = spec_.sky ? spec_.sky(glm::normalize(ray.direction)) : glm::vec3(0.0f);
  }
  return result;
}

glm::vec4 RayScene::pixelTruth(const FrameState& state, int i, int j, std::uint32_t seed,
                               int n) const {
  // A jittered n x n grid; a cell whose sample differs from a neighbour's is on an edge (or a
  // steep HDR slope) and is replaced by the mean of its own jittered sub-grid. Edge error of a
  // plain grid falls only as n^-1.5, too slowly for high-contrast wires and checkers. A ring of
  // cells just outside the pixel is sampled for the comparison only, so that edges running
  // along the pixel's border are found too.
  const int ring = n + 2;
  std::vector<glm::vec3> cells(std::size_t(ring) * ring);
  auto cell = [&](int a, int b) -> glm::vec3& { return cells[(b + 1) * ring + (a + 1)]; };
  const std::uint32_t pixel = pixelHash(seed, i, j);
  for (int b = -1; b <= n; ++b) {
    for (int a = -1; a <= n; ++a) {
      const glm::dvec2 u = unitPair(pixel, std::uint32_t((b + 1) * ring + (a + 1)));
      cell(a, b) = radiance(state, glm::dvec2(i + (a + u.x) / n, j + (b + u.y) / n));
    }
  }
  auto differs = [&](int a, int b, int a2, int b2) {
    const glm::vec3 d = glm::abs(cell(a, b) - cell(a2, b2));
    return std::max({d.x, d.y, d.z}) > kRefineThreshold;
  };
  glm::dvec3 sum(0.0);
  const int m = kRefinePerAxis;
  for (int b = 0; b < n; ++b) {
    for (int a = 0; a < n; ++a) {
      if (!differs(a, b, a - 1, b) && !differs(a, b, a + 1, b) && !differs(a, b, a, b - 1) &&
          !differs(a, b, a, b + 1)) {
        sum += glm::dvec3(cell(a, b));
        continue;
      }
      glm::dvec3 cellSum(0.0);
      for (int q = 0; q < m; ++q) {
        for (int p = 0; p < m; ++p) {
          const std::uint32_t k = std::uint32_t(ring * ring + (b * n + a) * m * m + q * m + p);
          const glm::dvec2 u = unitPair(pixel, k);
          cellSum += glm::dvec3(radiance(
              state, glm::dvec2(i + (a + (p + u.x) / m) / n, j + (b + (q + u.y) / m) / n)));
        }
      }
      sum += cellSum / double(m * m);
    }
  }
  return glm::vec4(glm::vec3(sum / double(n * n)), 1.0f);
}

RayScene::CentreMotion RayScene::centreMotion(const FrameState& other, glm::dvec2 centre,
                                              const Ray& ray, const Trace& hit) const {
  CentreMotion result;
  glm::dvec2 there(0.0);
  double depthThere = 0.0;
  bool inFront = true;
  if (hit.object >= 0) {
    // The same material point in the other frame: through this frame's object-to-local and
    // the other frame's object-to-world, then the other frame's camera.
    const glm::dvec3 world(other.objects[hit.object].toWorld * glm::dvec4(hit.hit.point, 1.0));
    there = other.camera.project(world, &depthThere);
    inFront = depthThere > 0.0;
    result.written = inFront ? there - centre : glm::dvec2(0.0);
  } else {
    inFront = other.camera.projectDirection(ray.direction, &there);
    result.written = glm::dvec2(0.0);  // as Cycles: no geometry, no vector
  }
  result.exact = inFront ? there - centre : glm::dvec2(0.0);
  if (!inFront || !onRaster(there, width(), height())) {
    result.disocclusion = kOutsideBefore;
    return result;
  }
  Trace before;
  const bool hitBefore = trace(other, other.camera.ray(there), &before);
  const bool same =
      hit.object < 0 ? !hitBefore
                     : hitBefore && before.object == hit.object &&
                           std::fabs(before.hit.t - depthThere) <= 1e-4 * depthThere + 1e-6;
  result.disocclusion = same ? kVisibleBefore : kOccludedBefore;
  return result;
}

Image RayScene::truthRegion(int frame, const RenderSettings& settings, int x0, int y0, int w,
                            int h) const {
  if (settings.truthSamplesPerAxis < 1) {
    throw Error("truth samples per axis must be at least 1", {"", frame, ""});
  }
  const FrameState now = state(frame);
  Image truth(w, h, 4);
  parallelFor(h, settings.threads, [&](int j) {
    for (int i = 0; i < w; ++i) {
      const glm::vec4 value =
          pixelTruth(now, x0 + i, y0 + j, settings.truthSeed, settings.truthSamplesPerAxis);
      std::copy(&value[0], &value[0] + 4, truth.at(i, j));
    }
  });
  return truth;
}

SceneFrame RayScene::render(int frame, const RenderSettings& settings) const {
  const int w = width(), h = height();
  SceneFrame out = blankFrame(frame, w, h, settings, false);
  out.shot = shot(frame);
  const FrameState now = state(frame), previous = state(frame - 1), next = state(frame + 1);
  out.hasCamera = true;
  out.camera.worldToCamera = glm::mat4(now.camera.worldToCamera());
  out.camera.worldToNDC = glm::mat4(now.camera.worldToNDC());
  const glm::dvec2 jitter(out.jitter);

  parallelFor(h, settings.threads, [&](int j) {
    for (int i = 0; i < w; ++i) {
      const glm::dvec2 centre(i + 0.5, j + 0.5);
      const glm::vec4 color(radiance(now, centre + jitter), 1.0f);
      std::copy(&color[0], &color[0] + 4, out.color.at(i, j));

      const Ray ray = now.camera.ray(centre);
      Trace hit;
      trace(now, ray, &hit);
      out.depth.at(i, j)[0] = hit.object >= 0 ? float(hit.hit.t) : float(kInf);
      const CentreMotion back = centreMotion(previous, centre, ray, hit);
      const CentreMotion forward = centreMotion(next, centre, ray, hit);
      out.motion.at(i, j)[0] = float(back.written.x);
      out.motion.at(i, j)[1] = float(back.written.y);
      out.nextMotion.at(i, j)[0] = float(forward.written.x);
      out.nextMotion.at(i, j)[1] = float(forward.written.y);
      out.flow.at(i, j)[0] = float(back.exact.x);
      out.flow.at(i, j)[1] = float(back.exact.y);
      out.disocclusion.at(i, j)[0] = float(back.disocclusion);
    }
  });
  out.truth = truthRegion(frame, settings, 0, 0, w, h);
  return out;
}

}  // namespace taa::scenes
