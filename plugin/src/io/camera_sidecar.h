// A JSON sidecar with per-frame camera matrices and jitter, for renderers that do not write
// them into the EXR header. Format (docs/ARCHITECTURE.md, "Camera sidecar"):
//   { "frames": { "1001": { "view": [16 numbers], "projection": [16 numbers],
//                           "jitter": [jx, jy] }, ... } }
// view and projection are OpenGL column-vector matrices listed column by column (as
// glm::value_ptr gives them): view maps world to a right-handed eye space looking down -z,
// projection maps eye space to clip space whose NDC is [-1, 1] with y up. jitter is the
// frame's sample offset from the pixel centre in pixels, x right, y down (DESIGN.md section 3).
// Each entry may omit the matrices (both or neither) or the jitter.
#pragma once

#include <glm/vec2.hpp>

#include <map>
#include <optional>
#include <string>

#include "resolve/camera.h"
#include "taa/error.h"

namespace taa::io {

struct SidecarFrame {
  std::optional<FrameCamera> camera;  // converted: +z-forward camera space, worldToNdc = P V
  std::optional<glm::vec2> jitter;
};

// Where an entry comes from, for its messages: `entry` names it ("sidecar entry"), `whole` the
// text that holds it ("the camera sidecar").
struct EntrySource {
  std::string entry, whole;
};

// One entry as JSON text (an object with "view", "projection", "jitter" as above), checked and
// converted as the sidecar's entries are: the camera note in an EXR header (io/camera_note.h)
// holds one. Throws taa::Error with `context` for malformed JSON or a malformed entry.
SidecarFrame parseCameraEntry(const std::string& text, const EntrySource& source,
                              const ErrorContext& context);

class CameraSidecar {
 public:
  // Reads and checks the whole file. Throws taa::Error naming the file (and the frame) for an
  // unreadable file, malformed JSON, or a malformed entry.
  static CameraSidecar load(const std::string& path);

  const std::string& path() const { return path_; }
  // The entry of `frame`; throws taa::Error naming the file and frame when it has none.
  const SidecarFrame& frame(int frame) const;
  // The frame's camera / jitter; throws taa::Error naming file and frame when absent.
  const FrameCamera& camera(int frame) const;
  glm::vec2 jitter(int frame) const;

  // The NDC convention of the sidecar's worldToNdc (OpenGL's).
  static constexpr NdcConvention kNdc = NdcConvention::MinusOneOneYUp;

 private:
  std::string path_;
  std::map<int, SidecarFrame> frames_;
};

}  // namespace taa::io
