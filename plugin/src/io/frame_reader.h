// Reads one frame's AOVs through OpenImageIO and converts them to internal conventions.
#pragma once

#include <OpenImageIO/imageio.h>

#include <functional>
#include <optional>
#include <string>

#include "io/aov_layout.h"
#include "io/camera_sidecar.h"
#include "io/exr_writer.h"
#include "resolve/camera.h"
#include "util/image.h"

namespace taa::io {

// Where a frame's camera matrices came from.
enum class CameraOrigin { None, Sidecar, Note, HeaderMatrices };

struct FrameData {
  int frame = 0;
  TypedImage color;  // RGBA, premultiplied as stored; half when the file's colour channels are
                    // all half, else float; NaN/Inf replaced by 0
  Image depth;   // 1 channel, planar, +inf = no hit; empty if the layout has no depth
  Image motion;  // 2 channels, pixels, y down, to previous; empty if the layout has no motion
  int nonFiniteColorValues = 0;   // how many color values were NaN/Inf and scrubbed to 0
  Image nonFiniteMask;            // 1 channel: 1 where a color value was scrubbed, else 0;
                                  // empty when none was
  int colorValuesBeyondHalf = 0;  // finite float color values beyond +-65504 (a half output
                                  // clamps them)
  int nonFiniteMotionValues = 0;  // motion values NaN/Inf (before or after conversion), set to 0
  std::string motionPath;         // the file motion came from; empty without motion
  std::optional<FrameCamera> camera;  // from the sidecar, else the color header's camera note,
                                      // else its worldToCamera + worldToNDC
  CameraOrigin cameraOrigin = CameraOrigin::None;  // which of those `camera` came from
  NdcConvention ndc = NdcConvention::ZeroOneYDown;  // the convention of camera->worldToNdc
  std::optional<glm::vec2> noteJitter;  // the color header's camera note's jitter, if it has one
  // Set by the sequence job: `camera`'s projection carried the frame's jitter, now taken out
  // (resolve/projection_jitter.h).
  bool jitterTakenOutOfProjection = false;
  RasterWindow window;            // the data window's place in the display window
  OIIO::ImageSpec colorSpec;      // the color part's header: windows and metadata for output
  int colorPart = 0;              // which part of the colour file that is
  std::string colorPath;
  ExtraChannels passthrough;      // the layout's pass-through channels, types kept
  // With AovLayout::passes: every other channel of the color part that is not dropped, in file
  // order, types kept (the color's own channels are not among them).
  ExtraChannels passes;
  // Set by the window resolve's reader (resolve/pass_plan): the summed passes packed for its
  // ring and each Cryptomatte set's first rank layer; `passes.image` then holds only the
  // channels taken from the frame as they are (keptChannels).
  std::vector<TypedImage> passGroups;
  std::vector<Image> passCryptomatte;
  // A multi-view job's other views of this frame (the job reads them: resolve/sequence_job),
  // each read with its view's layout; this one is the first view.
  std::vector<FrameData> otherViews;
};

// The largest data window side readFrame accepts: GPUs' texture limit (16384 on llvmpipe and
// most hardware), and a damaged header claiming 100000 x 100000 must not make taa allocate and
// clear tens of gigabytes before the read finds the file too short.
inline constexpr int kMaxImageSide = 16384;

// Where camera matrices come from besides the color header.
struct CameraInputs {
  NdcConvention headerNdc = NdcConvention::ZeroOneYDown;  // of the headers' worldToNDC
  const CameraSidecar* sidecar = nullptr;  // its entries with matrices replace the header's
  // Read the color header's camera note (io/camera_note.h): its matrices come after the
  // sidecar's and before worldToCamera/worldToNDC, its jitter goes to FrameData::noteJitter.
  // Off when the caller takes both camera and jitter from elsewhere (a bad note is then no error).
  bool readNote = true;
};

// Reads frame `frame`. All images cover the color part's data window. An AOV with an empty
// pattern is read from the color file, which is opened once. Channels are looked up by name in
// the AOV's part (multi-part files: by part name, or the first part holding every channel), in
// the order the layout lists them (not the file's order). Scanline and tiled files alike.
// Colour keeps its stored type (all half: half, else float); depth and motion are float.
// Conversions: color NaN/Inf -> 0 (counted), 3 channels or a 4th (alpha) channel missing from
// the file -> A = 1; depth per DepthConvention
// (radial depth uses the frame's camera, else the convention's field of view); motion per
// MotionConvention (Ndc and Uv units refer to the display window), then NaN/Inf -> 0 (counted).
// Throws taa::Error naming file, frame and channel for: a missing or unreadable file, a non-EXR
// (e.g. a PNG, whatever its name), truncated or corrupt file, a missing part (listing those
// available), a missing channel (listing those available), a wrong channel count for an AOV,
// depth/motion windows that differ from color's (stating both), radial depth without a camera,
// a data window beyond kMaxImageSide, a malformed camera note (channel "Note").
//
// With `passBands` (AovLayout::passes): the pass channels are not read into `passes.image`
// (which stays empty; names and formats are set); `passBands` is called once with them and the
// image size before any pixel is read, and what it returns gets each band of rows as it is
// decoded (ChannelRequest::band), so the frame's passes are never held whole as float.
// `decodeThreads`: io/part_channels' readPartChannels (above 1 only where the caller's other
// cores are idle while it reads; `passBands`' sink is then called from several threads).
using PassBandSink =
    std::function<void(std::size_t firstPixel, std::size_t count, const float* values)>;
using PassBandReceiver =
    std::function<PassBandSink(const ExtraChannels& passes, int width, int height)>;
FrameData readFrame(const AovLayout& layout, int frame, const CameraInputs& cameras = {},
                    const PassBandReceiver& passBands = {}, int decodeThreads = 1);

// The pass channels readFrame would read for `frame` (AovLayout::passes; none without it), names
// and types, and the image's size, from the colour file's header alone: a job decides from
// them how long a window its memory holds.
struct PassHeader {
  ExtraChannels channels;
  int width = 0, height = 0;
};
PassHeader readPassHeader(const AovLayout& layout, int frame);


}  // namespace taa::io
