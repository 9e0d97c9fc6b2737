#include "io/camera_sidecar.h"

#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <limits>

#include "resolve/jitter.h"
#include "taa/error.h"
#include "util/number_text.h"

namespace taa::io {
namespace {

using nlohmann::json;

const EntrySource kSidecarSource{"sidecar entry", "the camera sidecar"};

// A column-major 4x4 matrix from 16 numbers.
glm::dmat4 readMatrix(const json& value, const char* key, const EntrySource& source,
                      const ErrorContext& context) {
  if (!value.is_array() || value.size() != 16) {
    throw Error(source.entry + " \"" + key + "\" must be an array of 16 numbers", context);
  }
  double numbers[16];
  for (int i = 0; i < 16; ++i) {
    if (!value[i].is_number()) {
      throw Error(source.entry + " \"" + key + "\" holds a non-number", context);
    }
    numbers[i] = value[i].get<double>();
    // The GPU takes them as float: 1e300 would become infinity there, and NaN everywhere.
    if (!(std::abs(numbers[i]) <= double(std::numeric_limits<float>::max()))) {
      throw Error(source.entry + " \"" + key + "\" holds " + std::to_string(numbers[i]) +
                      ", beyond float's range",
                  context);
    }
  }
  return glm::make_mat4(numbers);
}

// A double as float; beyond float's range +-infinity (a plain conversion would be undefined).
float toFloat(double value) {
  const double limit = std::numeric_limits<float>::max();
  if (std::abs(value) <= limit) return float(value);
  return value > 0.0 ? std::numeric_limits<float>::infinity()
                     : -std::numeric_limits<float>::infinity();
}

SidecarFrame readEntry(const json& entry, const EntrySource& source,
                       const ErrorContext& context) {
  if (!entry.is_object()) throw Error(source.entry + " must be an object", context);
  SidecarFrame frame;
  const bool hasView = entry.contains("view"), hasProjection = entry.contains("projection");
  if (hasView != hasProjection) {
    throw Error(source.entry + " needs both \"view\" and \"projection\" (or neither)",
                context);
  }
  if (hasView) {
    const glm::dmat4 view = readMatrix(entry["view"], "view", source, context);
    const glm::dmat4 projection = readMatrix(entry["projection"], "projection", source, context);
    // OpenGL's eye space looks down -z; taa's camera space looks down +z (EXR convention).
    glm::dmat4 flipZ(1.0);
    flipZ[2][2] = -1.0;
    frame.camera = FrameCamera{flipZ * view, projection * view};
  }
  if (entry.contains("jitter")) {
    const json& j = entry["jitter"];
    if (!j.is_array() || j.size() != 2 || !j[0].is_number() || !j[1].is_number()) {
      throw Error(source.entry + " \"jitter\" must be [jx, jy] in pixels", context);
    }
    const glm::vec2 jitter(toFloat(j[0].get<double>()), toFloat(j[1].get<double>()));
    frame.jitter = checkedJitter(jitter, source.whole, context);
  }
  return frame;
}

int parseFrameKey(const std::string& key, const std::string& path) {
  const std::optional<int> frame = parseIntText(key);
  if (!frame) throw Error("sidecar frame key \"" + key + "\" is not a frame number", {path});
  return *frame;
}

}  // namespace

// A sidecar nests four levels deep (document, frames, entry, matrix). Deeper input is refused
// while it is read: 100 MB of '[' cost 3.8 GB as a document before its error (issue 25).
constexpr int kMaxJsonDepth = 16;

template <typename Input>
json parseShallowJson(Input&& input) {
  return json::parse(std::forward<Input>(input), [](int depth, json::parse_event_t, json&) {
    if (depth > kMaxJsonDepth) {
      throw Error("nests deeper than " + std::to_string(kMaxJsonDepth) + " levels");
    }
    return true;
  });
}

SidecarFrame parseCameraEntry(const std::string& text, const EntrySource& source,
                              const ErrorContext& context) {
  json entry;
  try {
    entry = parseShallowJson(text);
  } catch (const Error& e) {
    throw Error(source.whole + " is not a camera entry: it " + e.description(), context);
  } catch (const json::exception& e) {
    throw Error(source.whole + " is not valid JSON: " + e.what(), context);
  }
  return readEntry(entry, source, context);
}

CameraSidecar CameraSidecar::load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw Error("cannot read the camera sidecar", {path});
  json document;
  try {
    document = parseShallowJson(in);
  } catch (const Error& e) {
    throw Error("the camera sidecar " + e.description(), {path});
  } catch (const json::exception& e) {
    throw Error(std::string("the camera sidecar is not valid JSON: ") + e.what(), {path});
  }
  if (!document.is_object() || !document.contains("frames") || !document["frames"].is_object()) {
    throw Error("the camera sidecar has no \"frames\" object", {path});
  }
  CameraSidecar sidecar;
  sidecar.path_ = path;
  for (const auto& [key, entry] : document["frames"].items()) {
    const int frame = parseFrameKey(key, path);
    sidecar.frames_[frame] = readEntry(entry, kSidecarSource, {path, frame, ""});
  }
  return sidecar;
}

const SidecarFrame& CameraSidecar::frame(int frame) const {
  const auto found = frames_.find(frame);
  if (found == frames_.end()) throw Error("the camera sidecar has no entry for this frame",
                                          {path_, frame, ""});
  return found->second;
}

const FrameCamera& CameraSidecar::camera(int frame) const {
  const SidecarFrame& entry = this->frame(frame);
  if (!entry.camera) {
    throw Error("the camera sidecar's entry has no view/projection matrices", {path_, frame, ""});
  }
  return *entry.camera;
}

glm::vec2 CameraSidecar::jitter(int frame) const {
  const SidecarFrame& entry = this->frame(frame);
  if (!entry.jitter) throw Error("the camera sidecar's entry has no jitter", {path_, frame, ""});
  return *entry.jitter;
}

}  // namespace taa::io
