#include "scenegen/scenes_3d.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "scenegen/textures_3d.h"

namespace taa::scenes {
namespace {

using Transform = std::function<glm::dmat4(int)>;

Transform fixed(glm::dmat4 m) {
  return [m](int) { return m; };
}

glm::dmat4 translation(double x, double y, double z) {
  return glm::translate(glm::dmat4(1.0), glm::dvec3(x, y, z));
}

glm::dmat4 rotation(double degrees, glm::dvec3 axis) {
  return glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis);
}

// The local z = 0 plane laid flat as the world's y = height plane (local y runs toward -z).
glm::dmat4 floorAt(double height) {
  return translation(0.0, height, 0.0) * rotation(-90.0, {1.0, 0.0, 0.0});
}

// A horizontal wire along world x: the cylinder's local y axis turned onto x.
glm::dmat4 horizontalWire(double y, double z) {
  return translation(0.0, y, z) * rotation(90.0, {0.0, 0.0, 1.0});
}

Shape rectangle(double halfWidth = 0.0, double halfHeight = 0.0) {
  return {ShapeKind::Rectangle, {halfWidth, halfHeight, 0.0}};
}
Shape box(double x, double y, double z) { return {ShapeKind::Box, {x, y, z}}; }
Shape sphere(double radius) { return {ShapeKind::Sphere, {radius, 0.0, 0.0}}; }
Shape cylinder(double radius, double halfLength) {
  return {ShapeKind::Cylinder, {radius, halfLength, 0.0}};
}

std::function<glm::vec3(const SurfacePoint&)> matte(glm::vec3 albedo) {
  return [albedo](const SurfacePoint& p) { return lambert(albedo, p.worldNormal); };
}

// A fogged checker floor; the fog removes contrast where cells would be far below a pixel.
SceneObject checkerFloor(double cell, double fogRange) {
  return {rectangle(), fixed(floorAt(0.0)), {}, [cell, fogRange](const SurfacePoint& p) {
            const glm::vec3 c = checker({p.local.x, p.local.y}, cell, glm::vec3(0.85f),
                                        glm::vec3(0.06f, 0.07f, 0.08f));
            const double distance = glm::length(p.world - p.cameraPosition);
            return fog(lambert(c, p.worldNormal), glm::vec3(0.45f, 0.47f, 0.5f), distance,
                       fogRange);
          }};
}

SceneObject brickWall(double z, double halfWidth, double halfHeight, double centreY) {
  return {rectangle(halfWidth, halfHeight), fixed(translation(0.0, centreY, z)), {},
          [](const SurfacePoint& p) {
            const glm::vec3 c = bricks({p.local.x, p.local.y}, 0.42, 0.21, 0.025,
                                       glm::vec3(0.7f, 0.28f, 0.15f), glm::vec3(0.85f));
            return lambert(c, p.worldNormal);
          }};
}

// 1. Thin wires and a chain-link fence against a bright backdrop, slow pan with parallax.
RaySceneSpec wires() {
  RaySceneSpec s;
  s.camera = [](int f) {
    return CameraPose{{-0.6 + 0.025 * f, 1.6, 0.0}, -3.0 + 0.12 * f, 4.0, 40.0};
  };
  s.sky = daySky;
  const glm::vec3 metal(0.06f, 0.06f, 0.07f);
  s.objects.push_back({rectangle(), fixed(translation(0.0, 0.0, -40.0)), {},
                       [](const SurfacePoint& p) {
                         // Float sines (as below and in daySky): half the time of double
                         // ones, and exact enough for a faint modulation.
                         const float v = 0.1f * std::sin(float(0.35 * p.local.x)) *
                                         std::sin(float(0.5 * p.local.y));
                         return glm::vec3(1.1f + v, 1.05f + v, 0.95f);
                       }});
  s.objects.push_back({rectangle(6.0, 1.25), fixed(translation(0.0, 1.25, -8.0)),
                       [](glm::dvec3 l) { return chainLink({l.x, l.y}, 0.2, 0.012); },
                       matte(metal)});
  s.objects.push_back({cylinder(0.02, 6.0), fixed(horizontalWire(2.5, -7.99)), {},
                       matte(metal)});
  for (double x : {-6.0, -2.0, 2.0, 6.0}) {
    s.objects.push_back({cylinder(0.04, 1.3), fixed(translation(x, 1.3, -7.98)), {},
                         matte(metal)});
  }
  for (double y : {5.0, 5.35, 5.7}) {
    s.objects.push_back({cylinder(0.008, 40.0), fixed(horizontalWire(y, -15.0)), {},
                         matte(glm::vec3(0.02f))});
  }
  s.objects.push_back({rectangle(), fixed(floorAt(0.0)), {}, [](const SurfacePoint& p) {
                         const float v = 0.05f * std::sin(float(3.0 * p.local.x)) *
                                         std::sin(float(2.3 * p.local.y));
                         return lambert(glm::vec3(0.25f + v, 0.3f + v, 0.18f), p.worldNormal);
                       }});
  return s;
}

// 2. A fine checker floor at a grazing angle, the camera dollying forward.
RaySceneSpec checkerDolly() {
  RaySceneSpec s;
  s.camera = [](int f) { return CameraPose{{0.1, 1.2, 2.0 - 0.15 * f}, 8.0, -7.0, 40.0}; };
  s.sky = daySky;
  s.objects.push_back(checkerFloor(0.4, 14.0));
  return s;
}

// 3. Objects crossing in front of a textured wall: background uncovered behind them and
// covered in front, a box spinning as it goes.
RaySceneSpec movingObject() {
  RaySceneSpec s;
  s.camera = [](int) { return CameraPose{{0.0, 1.5, 0.0}, 0.0, -4.0, 40.0}; };
  s.sky = daySky;
  s.objects.push_back(brickWall(-12.0, 12.0, 5.0, 5.0));
  s.objects.push_back(checkerFloor(0.6, 30.0));
  s.objects.push_back({box(0.45, 0.45, 0.45),
                       [](int f) {
                         return translation(-2.2 + 0.13 * f, 1.2, -7.0) *
                                rotation(4.0 * f, {0.0, 1.0, 0.0});
                       },
                       {}, [](const SurfacePoint& p) {
                         const bool stripe = periodFraction(p.local.x + p.local.y + p.local.z,
                                                            0.09) < 0.5;
                         return lambert(stripe ? glm::vec3(0.1f, 0.4f, 0.9f)
                                               : glm::vec3(0.9f, 0.9f, 0.2f),
                                        p.worldNormal);
                       }});
  s.objects.push_back({sphere(0.6),
                       [](int f) {
                         return translation(2.4 - 0.11 * f, 1.9, -9.0) *
                                rotation(-3.0 * f, {0.0, 1.0, 0.0});
                       },
                       {}, [](const SurfacePoint& p) {
                         const double lon = std::atan2(p.local.z, p.local.x);
                         const double lat = std::asin(std::clamp(p.local.y / 0.6, -1.0, 1.0));
                         return lambert(checker({lon, lat}, 0.2, glm::vec3(0.9f),
                                                glm::vec3(0.1f, 0.6f, 0.15f)),
                                        p.worldNormal);
                       }});
  return s;
}

// 4. The camera yaws while an object spins in front of pillars and a striped wall.
RaySceneSpec rotateYaw() {
  RaySceneSpec s;
  s.camera = [](int f) { return CameraPose{{0.0, 1.7, 3.0}, -5.0 + 0.35 * f, -8.0, 40.0}; };
  s.sky = daySky;
  s.objects.push_back(checkerFloor(0.5, 20.0));
  s.objects.push_back({rectangle(20.0, 4.0), fixed(translation(0.0, 4.0, -9.0)), {},
                       [](const SurfacePoint& p) {
                         const bool stripe = periodFraction(p.local.x + 0.3 * p.local.y, 0.2) <
                                             0.35;
                         return lambert(stripe ? glm::vec3(0.8f, 0.75f, 0.6f)
                                               : glm::vec3(0.2f, 0.1f, 0.08f),
                                        p.worldNormal);
                       }});
  s.objects.push_back({box(0.6, 0.6, 0.6),
                       [](int f) {
                         return translation(0.0, 0.62, -3.5) * rotation(6.0 * f, {0.0, 1.0, 0.0});
                       },
                       {}, [](const SurfacePoint& p) {
                         // Checkered sides; the top, seen at a grazing angle, is plain.
                         if (std::fabs(p.localNormal.y) > 0.5) {
                           return lambert(glm::vec3(0.5f, 0.2f, 0.15f), p.worldNormal);
                         }
                         return lambert(checker({p.local.x + p.local.z, p.local.y}, 0.15,
                                                glm::vec3(0.95f, 0.3f, 0.2f), glm::vec3(0.05f)),
                                        p.worldNormal);
                       }});
  for (double x : {-3.0, -1.6, 1.6, 3.0, 4.4}) {
    s.objects.push_back({cylinder(0.12, 2.0), fixed(translation(x, 2.0, -6.0)), {},
                         matte(glm::vec3(0.75f))});
  }
  return s;
}

// 5. Small HDR lights (10-1000) and a glossy highlight on a dark wall, slow pan and bob.
RaySceneSpec hdrHighlights() {
  RaySceneSpec s;
  s.camera = [](int f) {
    return CameraPose{{0.02 * f, 1.5 + 0.05 * std::sin(0.4 * f), 0.0}, 0.08 * f, 0.0, 40.0};
  };
  s.objects.push_back({rectangle(), fixed(translation(0.0, 0.0, -10.0)), {},
                       [](const SurfacePoint& p) {
                         const glm::dvec2 q(p.local.x, p.local.y);
                         glm::vec3 c(0.015f, 0.018f, 0.025f);
                         // A grid of lights, each with its own brightness and size.
                         const glm::dvec2 cell(std::floor(q.x / 0.9), std::floor(q.y / 0.7));
                         const glm::dvec2 centre((cell.x + 0.5) * 0.9, (cell.y + 0.5) * 0.7);
                         const double distance = glm::length(q - centre);
                         if (distance < 0.08) {  // every radius is less: beyond, skip the hash
                           const double id = periodFraction(
                               std::sin(cell.x * 12.99 + cell.y * 78.23) * 43758.5, 1.0);
                           const double radius = 0.03 + 0.05 * id;
                           const double peak = 10.0 * std::pow(100.0, id);
                           const double bump = smoothBump(distance, radius);
                           c += glm::vec3(1.0f, 0.85f, 0.6f) * float(peak * bump);
                         }
                         // Neon strips with a smooth cross-section.
                         const double band = smoothBump(
                             std::fabs(periodFraction(q.y, 1.6) - 0.5) * 1.6, 0.03);
                         c += glm::vec3(0.3f, 1.0f, 4.0f) * float(20.0 * band);
                         return c;
                       }});
  s.objects.push_back({sphere(0.5), fixed(translation(-0.8, 1.2, -5.0)), {},
                       [](const SurfacePoint& p) {
                         static const glm::dvec3 light =
                             glm::normalize(glm::dvec3(-0.3, 0.6, 0.7));
                         const glm::dvec3 toEye = glm::normalize(p.cameraPosition - p.world);
                         const glm::dvec3 half = glm::normalize(light + toEye);
                         const double spec = std::pow(std::max(0.0, glm::dot(p.worldNormal,
                                                                             half)), 400.0);
                         return glm::vec3(0.03f, 0.02f, 0.02f) + glm::vec3(float(500.0 * spec));
                       }});
  return s;
}

// 6. Only sky: a rotating camera and no geometry, so the written vectors are all zero.
RaySceneSpec skyPan() {
  RaySceneSpec s;
  s.camera = [](int f) { return CameraPose{{0.0, 0.0, 0.0}, 0.4 * f, 12.0 + 0.05 * f, 40.0}; };
  s.sky = [](glm::dvec3 d) {
    glm::vec3 c = daySky(d);
    const double azimuth = glm::degrees(std::atan2(d.x, -d.z));
    const double elevation = glm::degrees(std::asin(std::clamp(d.y, -1.0, 1.0)));
    // Thin bright contrails and a fine dark lattice of cirrus lines in angle space.
    if (periodFraction(azimuth + 0.5 * elevation, 7.3) < 0.03) c = glm::vec3(1.6f);
    if (periodFraction(elevation, 1.7) < 0.12) c *= 0.7f;
    static const glm::dvec3 sun = glm::normalize(glm::dvec3(0.3, 0.25, -1.0));
    c += glm::vec3(30.0f, 27.0f, 20.0f) * float(smoothBump(glm::length(d - sun), 0.02));
    return c;
  };
  return s;
}

// 7. A hard cut: shot 0 looks down -z at bricks and a sphere, shot 1 turns round to a checker
// floor and boxes behind the first camera.
RaySceneSpec cut() {
  RaySceneSpec s = movingObject();
  s.camera = [](int f) {
    if (f < kCutFrame) return CameraPose{{0.0, 1.5, 0.0}, -2.0 + 0.1 * f, -4.0, 40.0};
    return CameraPose{{0.5, 1.8, 1.0}, 170.0 + 0.15 * f, -10.0, 40.0};
  };
  s.shot = [](int f) { return f < kCutFrame ? 0 : 1; };
  for (double x : {-1.5, 0.0, 1.5}) {
    s.objects.push_back({box(0.35, 0.5, 0.35), fixed(translation(x, 0.5, 6.0 + 0.4 * x)), {},
                         [](const SurfacePoint& p) {
                           return lambert(checker({p.local.x + p.local.z, p.local.y}, 0.1,
                                                  glm::vec3(0.2f, 0.8f, 0.3f),
                                                  glm::vec3(0.9f)),
                                          p.worldNormal);
                         }});
  }
  return s;
}

}  // namespace

const std::vector<SceneInfo>& scene3dList() {
  static const std::vector<SceneInfo> list = {
      {"wires", "3D: chain-link fence and sub-pixel wires against a bright backdrop, slow pan"},
      {"checker_dolly", "3D: fine checker floor at a grazing angle, camera dollying forward"},
      {"moving_object_3d", "3D: a spinning box and a sphere crossing a brick wall, static camera"},
      {"rotate_yaw", "3D: camera yaw, a box spinning in front of pillars and a striped wall"},
      {"hdr_highlights", "3D: small lights (10-1000) and a glossy highlight on a dark wall"},
      {"sky_pan", "3D: sky only, rotating camera, zero motion vectors (as Cycles writes)"},
      {"cut", "3D: a hard cut to a different view at frame 13"},
  };
  return list;
}

std::unique_ptr<RayScene> makeScene3d(const std::string& name, int width, int height) {
  RaySceneSpec spec;
  if (name == "wires") {
    spec = wires();
  } else if (name == "checker_dolly") {
    spec = checkerDolly();
  } else if (name == "moving_object_3d") {
    spec = movingObject();
  } else if (name == "rotate_yaw") {
    spec = rotateYaw();
  } else if (name == "hdr_highlights") {
    spec = hdrHighlights();
  } else if (name == "sky_pan") {
    spec = skyPan();
  } else if (name == "cut") {
    spec = cut();
  } else {
    return nullptr;
  }
  return std::make_unique<RayScene>(name, width, height, std::move(spec));
}

}  // namespace taa::scenes
