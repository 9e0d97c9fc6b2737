#include "io/frame_reader.h"

#include <fnmatch.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <deque>
#include <filesystem>
#include <functional>
#include <limits>
#include <memory>
#include <system_error>
#include <type_traits>

#include "io/aov_conversion.h"
#include "io/camera_note.h"
#include "io/exr_chunk_check.h"
#include "io/file_presence.h"
#include "io/layout_hint.h"
#include "io/part_channels.h"
#include "io/sequence_pattern.h"
#include "io/views.h"
#include "taa/error.h"

namespace taa::io {
namespace {

std::string joinNames(const std::vector<std::string>& names) {
  std::string joined;
  for (const std::string& name : names) joined += (joined.empty() ? "" : ", ") + name;
  return joined;
}

std::string describeWindow(const OIIO::ImageSpec& spec) {
  return std::to_string(spec.width) + "x" + std::to_string(spec.height) + " at (" +
         std::to_string(spec.x) + ", " + std::to_string(spec.y) + ")";
}

// An open EXR file, shared by every AOV that lives in it, with the header of each part.
struct OpenExr {
  std::string path;
  std::unique_ptr<OIIO::ImageInput> input;
  std::vector<OIIO::ImageSpec> parts;  // subimages, in file order
};

std::string partName(const OIIO::ImageSpec& spec) {
  std::string name = spec.get_string_attribute("name");
  if (name.empty()) name = spec.get_string_attribute("oiio:subimagename");
  return name;
}

// The first four bytes of every OpenEXR file.
constexpr unsigned char kExrMagic[4] = {0x76, 0x2f, 0x31, 0x01};

// Opens `path` with OIIO's OpenEXR reader only. A file that is not EXR (a PNG named .exr) is
// refused naming the format it reads as; a damaged EXR never reaches the readers of other
// formats (OIIO tries every plugin it has on a file its named reader refuses: DICOM, FITS...,
// each loaded at a cost in time and memory, their bugs not ours to meet).
OpenExr openExr(const std::string& path, const std::string& aovName, int frame) {
  const ErrorContext context{path, frame, ""};
  if (const std::string absence = fileAbsence(path); absence == "missing") {
    throw Error("cannot find the " + aovName + " file", context);
  } else if (!absence.empty()) {
    throw Error("the " + aovName + " file is " + absence, context);
  }
  unsigned char magic[4] = {};
  if (std::FILE* file = std::fopen(path.c_str(), "rb")) {
    const std::size_t got = std::fread(magic, 1, sizeof magic, file);
    std::fclose(file);
    if (got != sizeof magic || std::memcmp(magic, kExrMagic, sizeof magic) != 0) {
      std::string readsAs;  // only to name it: OIIO tries every format it knows
      if (auto other = OIIO::ImageInput::open(path)) {
        readsAs = std::string(" (it reads as ") + other->format_name() + ")";
      }
      OIIO::geterror();  // clear what the failed attempts left
      throw Error("the " + aovName + " file is not an OpenEXR file" + readsAs, context);
    }
  } else {  // OIIO would report "not an OpenEXR file": say why it cannot be read
    throw Error("cannot read the " + aovName + " file: " + std::strerror(errno), context);
  }
  auto input = OIIO::ImageInput::create("openexr");
  OIIO::ImageSpec first;
  if (!input || !input->open(path, first)) {
    std::string reason = input ? input->geterror() : OIIO::geterror();
    if (reason.empty()) reason = "unknown error";
    throw Error("cannot read the " + aovName + " file as OpenEXR: " + reason, context);
  }
  std::vector<OIIO::ImageSpec> parts;
  for (int subimage = 0; input->seek_subimage(subimage, 0); ++subimage) {
    parts.push_back(input->spec());
    if (parts.back().deep) throw Error("deep EXR files are not supported", context);
    if (parts.back().depth != 1) throw Error("volume (3D) EXR files are not supported", context);
    const OIIO::ImageSpec& part = parts.back();
    if (part.width <= 0 || part.height <= 0 || part.width > kMaxImageSide ||
        part.height > kMaxImageSide) {
      throw Error("the " + aovName + " file's data window " + describeWindow(part) +
                      " is not 1 to " + std::to_string(kMaxImageSide) + " pixels a side",
                  context);
    }
  }
  if (parts.empty()) throw Error("the " + aovName + " file has no image part", context);
  if (const std::string mismatch = firstChunkMismatch(path); !mismatch.empty()) {
    throw Error("the " + aovName + " file's data window is wider than its pixel data (" +
                    mismatch + "): a damaged or edited header",
                context);
  }
  return {path, std::move(input), std::move(parts)};
}

bool hasChannels(const OIIO::ImageSpec& spec, const std::vector<std::string>& names) {
  return std::all_of(names.begin(), names.end(), [&](const std::string& name) {
    return std::find(spec.channelnames.begin(), spec.channelnames.end(), name) !=
           spec.channelnames.end();
  });
}

// The part an AOV reads: the one named `source.part`, else the first holding every channel
// (part 0 when none does, so that the missing-channel error names what part 0 has).
int findPart(const OpenExr& file, const AovSource& source, const std::string& aovName,
             int frame) {
  if (!source.part.empty()) {
    std::string names;
    for (std::size_t i = 0; i < file.parts.size(); ++i) {
      if (partName(file.parts[i]) == source.part) return int(i);
      names += (names.empty() ? "" : ", ") + partName(file.parts[i]);
    }
    throw Error("the " + aovName + " file has no part named " + source.part +
                    "; parts available: " + (names.empty() ? "(unnamed)" : names),
                {file.path, frame, joinNames(source.channels)});
  }
  for (std::size_t i = 0; i < file.parts.size(); ++i) {
    if (hasChannels(file.parts[i], source.channels)) return int(i);
  }
  return 0;
}

// The indices of `names` in part `part`, in the order asked; a missing channel is an error
// listing what the file has.
std::vector<int> channelIndices(const OpenExr& file, int part,
                                const std::vector<std::string>& names, const std::string& aovName,
                                int frame) {
  const OIIO::ImageSpec& spec = file.parts[std::size_t(part)];
  std::vector<int> indices;
  std::vector<std::string> missing;
  for (const std::string& name : names) {
    const auto found = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
    if (found == spec.channelnames.end()) {
      missing.push_back(name);
    } else {
      indices.push_back(static_cast<int>(found - spec.channelnames.begin()));
    }
  }
  if (!missing.empty()) {
    std::string available = joinNames(spec.channelnames);
    for (std::size_t i = 0; i < file.parts.size() && file.parts.size() > 1; ++i) {
      available += (i == 0 ? " (part " : "; part ") + partName(file.parts[i]) + ": " +
                   joinNames(file.parts[i].channelnames) + (i + 1 == file.parts.size() ? ")" : "");
    }
    const std::string hint = layoutHint(spec, missing);
    throw Error("the " + aovName + " file lacks channel" + (missing.size() > 1 ? "s " : " ") +
                    joinNames(missing) + (hint.empty() ? "" : "; " + hint) +
                    "; channels available: " + available,
                {file.path, frame, joinNames(missing)});
  }
  return indices;
}

// Colour, depth and motion are half or float: an integer channel (an ID or count pass named by
// mistake) would come back scaled by OIIO into [0, 1] without a word.
void requireHalfOrFloat(const OpenExr& file, int part, const std::vector<std::string>& names,
                        const std::string& aovName, int frame) {
  const OIIO::ImageSpec& spec = file.parts[std::size_t(part)];
  for (int c : channelIndices(file, part, names, aovName, frame)) {
    const OIIO::TypeDesc type = spec.channelformat(c);
    if (type == OIIO::TypeHalf || type == OIIO::TypeFloat) continue;
    throw Error("the " + aovName + " channel " + spec.channelnames[std::size_t(c)] + " is " +
                    type.c_str() + ", not half or float: an integer pass (IDs, counts) is no " +
                    aovName + "; name another channel or pass it through (--passthrough)",
                {file.path, frame, spec.channelnames[std::size_t(c)]});
  }
}

// A frame's pixel reads, gathered by file and part before any is made, so that a part several
// AOVs share (a multilayer file's colour, depth and vectors) is decoded once.
class PartReads {
 public:
  // `names` of part `part` of `file` into `out` (interleaved, `outChannels` a pixel, the first
  // names.size() written), as `type`. Missing channels are an error at once.
  // With `band`, rows go to it as they are decoded instead (ChannelRequest::band).
  void add(OpenExr& file, int part, const std::vector<std::string>& names,
           const std::string& aovName, int frame, OIIO::TypeDesc type, void* out,
           int outChannels, PassBandSink band = {}) {
    ChannelRequest request{aovName, channelIndices(file, part, names, aovName, frame), names,
                           type, out, outChannels, std::move(band)};
    for (Group& group : groups_) {
      if (group.file == &file && group.part == part) {
        group.requests.push_back(std::move(request));
        return;
      }
    }
    groups_.push_back({&file, part, {std::move(request)}});
  }

  void readAll(int frame, int decodeThreads) {
    for (const Group& group : groups_) {
      readPartChannels(*group.file->input, group.file->path, frame, group.part,
                       group.file->parts[std::size_t(group.part)], group.requests,
                       decodeThreads);
    }
  }

 private:
  struct Group {
    OpenExr* file;
    int part;
    std::vector<ChannelRequest> requests;
  };
  std::vector<Group> groups_;
};

// Opens files once per frame, however many AOVs share them.
class FileSet {
 public:
  explicit FileSet(int frame) : frame_(frame) {}

  OpenExr& get(const std::string& path, const std::string& aovName) {
    for (OpenExr& file : files_) {
      if (file.path == path) return file;
    }
    files_.push_back(openExr(path, aovName, frame_));
    return files_.back();
  }

 private:
  int frame_;
  std::deque<OpenExr> files_;  // a deque keeps references valid as files are added
};

void requireChannelCount(const AovSource& source, std::size_t low, std::size_t high,
                         const std::string& aovName, int frame) {
  const std::size_t count = source.channels.size();
  if (count < low || count > high) {
    const std::string wanted = low == high ? std::to_string(low)
                                           : std::to_string(low) + " or " + std::to_string(high);
    throw Error("the " + aovName + " needs " + wanted + " channels, " + std::to_string(count) +
                    " given",
                {"", frame, joinNames(source.channels)});
  }
}

// Every AOV must cover exactly the color's pixels; resampling is not taa's job. Either file may
// be the odd one out (a colour frame rendered at the wrong size is as likely as a wrong depth
// frame), so the message names both files with their windows.
void requireSameWindow(const OpenExr& file, int part, const OIIO::ImageSpec& colorSpec,
                       const std::string& colorPath, const std::string& aovName, int frame) {
  const OIIO::ImageSpec& spec = file.parts[std::size_t(part)];
  if (spec.x != colorSpec.x || spec.y != colorSpec.y || spec.width != colorSpec.width ||
      spec.height != colorSpec.height) {
    throw Error("the " + aovName + " data window " + describeWindow(spec) + " (" + file.path +
                    ") differs from the color data window " + describeWindow(colorSpec) + " (" +
                    colorPath + ")",
                {file.path, frame, ""});
  }
}

std::string aovPath(const AovSource& source, const std::string& colorPath, int frame) {
  return source.pattern.empty() ? colorPath : expandFramePattern(source.pattern, frame);
}

// Half when the file stores every asked colour channel as half (it stays half up to the GPU and
// back), else float.
SampleType colorSampleType(const OIIO::ImageSpec& spec, const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    const auto found = std::find(spec.channelnames.begin(), spec.channelnames.end(), name);
    if (found == spec.channelnames.end()) return SampleType::Float;  // the read reports it
    if (spec.channelformat(int(found - spec.channelnames.begin())) != OIIO::TypeHalf) {
      return SampleType::Float;
    }
  }
  return SampleType::Half;
}

constexpr float kHalfMax = 65504.0f;

bool isFinite(float value) { return std::isfinite(value); }
bool isFinite(Imath::half value) { return value.isFinite(); }

// Fills alpha with 1 when the colour has 3 channels, replaces NaN/Inf by 0 and counts them, and
// counts the finite values a half output cannot hold. The mask (1 where a value was replaced) is
// made only when some value is.
template <typename T>
void finishRgba(ImageOf<T>& rgba, int inputChannels, FrameData& data) {
  const std::size_t pixelCount = std::size_t(rgba.width) * rgba.height;
  if (inputChannels == 3) {
    for (std::size_t pixel = 0; pixel < pixelCount; ++pixel) rgba.pixels[pixel * 4 + 3] = T(1.0f);
  }
  for (std::size_t i = 0; i < rgba.pixels.size(); ++i) {
    if (isFinite(rgba.pixels[i])) {
      if constexpr (std::is_same_v<T, float>) {
        if (std::abs(rgba.pixels[i]) > kHalfMax) ++data.colorValuesBeyondHalf;
      }
      continue;
    }
    rgba.pixels[i] = T(0.0f);
    ++data.nonFiniteColorValues;
    if (data.nonFiniteMask.empty()) data.nonFiniteMask = Image(rgba.width, rgba.height, 1);
    data.nonFiniteMask.pixels[i / 4] = 1.0f;
  }
}

// The colour channels of `source` as RGBA in their stored type (see colorSampleType), to be
// filled by `reads`. The fourth (alpha) is optional: a file without it reads as opaque, A = 1
// (finishColor). Returns how many channels are read.
int addColorRead(PartReads& reads, OpenExr& file, int part, const AovSource& source, int frame,
                 TypedImage& rgba) {
  const OIIO::ImageSpec& spec = file.parts[std::size_t(part)];
  std::vector<std::string> names = source.channels;
  if (names.size() == 4 && !hasChannels(spec, {names[3]})) names.pop_back();
  const SampleType type = colorSampleType(spec, names);
  rgba = TypedImage(spec.width, spec.height, 4, type);
  requireHalfOrFloat(file, part, names, "color", frame);
  reads.add(file, part, names, "color", frame,
            type == SampleType::Half ? OIIO::TypeHalf : OIIO::TypeFloat, rgba.data(), 4);
  return int(names.size());
}

void finishColor(FrameData& data, int inputChannels) {
  if (HalfImage* half = data.color.halves()) {
    finishRgba(*half, inputChannels, data);
  } else {
    finishRgba(*data.color.floats(), inputChannels, data);
  }
}

// The header's camera, if it has both matrices. EXR matrices act on row vectors (p' = p M) and
// are stored row by row; read as GLM's column-major storage, that is exactly the transpose,
// which acts on column vectors as GLM expects.
std::optional<FrameCamera> headerCamera(const OIIO::ImageSpec& spec, const std::string& path,
                                        int frame) {
  const OIIO::ParamValue* toCamera = spec.find_attribute("worldToCamera", OIIO::TypeMatrix44);
  const OIIO::ParamValue* toNdc = spec.find_attribute("worldToNDC", OIIO::TypeMatrix44);
  if (!toCamera || !toNdc) return std::nullopt;
  for (const OIIO::ParamValue* matrix : {toCamera, toNdc}) {
    const float* values = static_cast<const float*>(matrix->data());
    if (!std::all_of(values, values + 16, [](float v) { return std::isfinite(v); })) {
      throw Error("the color header's " + matrix->name().string() + " holds NaN or Inf",
                  {path, frame, ""});
    }
  }
  FrameCamera camera;
  camera.worldToCamera = glm::dmat4(glm::make_mat4(static_cast<const float*>(toCamera->data())));
  camera.worldToNdc = glm::dmat4(glm::make_mat4(static_cast<const float*>(toNdc->data())));
  return camera;
}

RasterWindow rasterWindow(const OIIO::ImageSpec& spec) {
  return {spec.x - spec.full_x, spec.y - spec.full_y,
          spec.full_width > 0 ? spec.full_width : spec.width,
          spec.full_height > 0 ? spec.full_height : spec.height};
}

// The sidecar's matrices when it has them for this frame, else the header's camera note's,
// else the header's worldToCamera/worldToNDC. The note's jitter is kept either way.
void chooseCamera(FrameData& data, const CameraInputs& cameras) {
  std::optional<SidecarFrame> note;
  if (cameras.readNote) note = readCameraNote(data.colorSpec, data.colorPath, data.frame);
  if (note) data.noteJitter = note->jitter;
  const SidecarFrame* entry = cameras.sidecar ? &cameras.sidecar->frame(data.frame) : nullptr;
  if (entry && entry->camera) {
    data.camera = entry->camera;
    data.cameraOrigin = CameraOrigin::Sidecar;
    data.ndc = CameraSidecar::kNdc;
  } else if (note && note->camera) {
    data.camera = note->camera;
    data.cameraOrigin = CameraOrigin::Note;
    data.ndc = CameraSidecar::kNdc;  // the note holds a sidecar entry: OpenGL's matrices
  } else {
    data.camera = headerCamera(data.colorSpec, data.colorPath, data.frame);
    data.cameraOrigin = data.camera ? CameraOrigin::HeaderMatrices : CameraOrigin::None;
    data.ndc = cameras.headerNdc;
  }
}

PixelRay pixelRayFor(const FrameData& data, const DepthConvention& convention,
                     const std::string& depthPath) {
  if (data.camera) return cameraPixelRay(*data.camera, data.window, data.ndc);
  if (convention.horizontalFovDegrees) {
    return pinholePixelRay(*convention.horizontalFovDegrees, data.window);
  }
  throw Error("radial depth needs the camera: worldToCamera/worldToNDC in the color header, a "
              "camera sidecar, or a field of view (--depth-fov)",
              {depthPath, data.frame, ""});
}

// The channels of the color part that `wanted` picks, in file order, with their types (half
// stays half, anything else is read as float): the extra channels a frame carries to its
// output.
ExtraChannels pickedChannels(const OIIO::ImageSpec& spec,
                             const std::function<bool(const std::string&)>& wanted) {
  ExtraChannels extra;
  for (int c = 0; c < spec.nchannels; ++c) {
    const std::string& name = spec.channelnames[std::size_t(c)];
    if (!wanted(name)) continue;
    extra.names.push_back(name);
    extra.formats.push_back(spec.channelformat(c) == OIIO::TypeHalf ? OIIO::TypeHalf
                                                                   : OIIO::TypeFloat);
  }
  return extra;
}

// Channels of the color part whose names match any pattern, to be filled by `reads`.
void addPassthroughRead(PartReads& reads, OpenExr& file, int part,
                        const std::vector<std::string>& patterns, int frame, ExtraChannels& extra) {
  if (patterns.empty()) return;
  const OIIO::ImageSpec& spec = file.parts[std::size_t(part)];
  extra = pickedChannels(spec, [&](const std::string& name) {
    return std::any_of(patterns.begin(), patterns.end(), [&](const std::string& p) {
      return ::fnmatch(p.c_str(), name.c_str(), 0) == 0;
    });
  });
  if (extra.names.empty()) return;
  extra.image = Image(spec.width, spec.height, int(extra.names.size()));
  reads.add(file, part, extra.names, "color", frame, OIIO::TypeFloat, extra.image.pixels.data(),
            extra.image.channels);
}

// Every channel of the color part but the color's own and those dropped (of a one-part
// multi-view file: of the layout's view): the passes resolved beside the beauty.
ExtraChannels passChannels(const OIIO::ImageSpec& spec, const AovLayout& layout) {
  const std::vector<ChannelKindRule> rules = passRulesOf(layout);
  const auto& color = layout.color.channels;
  return pickedChannels(spec, [&](const std::string& name) {
    const bool ofView = layout.view.empty() || viewOfChannel(name, layout.fileViews) == layout.view;
    return ofView && std::find(color.begin(), color.end(), name) == color.end() &&
           channelKind(withoutView(name, layout.view), rules) != ChannelKind::Drop;
  });
}

// The passes (AovLayout::passes), read whole or handed to `passBands` band by band.
void addPassesRead(PartReads& reads, OpenExr& file, int part, const AovLayout& layout, int frame,
                   ExtraChannels& passes, const PassBandReceiver& passBands) {
  const OIIO::ImageSpec& spec = file.parts[std::size_t(part)];
  passes = passChannels(spec, layout);
  if (passes.names.empty()) return;
  if (passBands) {
    reads.add(file, part, passes.names, "color", frame, OIIO::TypeFloat, nullptr,
              int(passes.names.size()), passBands(passes, spec.width, spec.height));
    return;
  }
  passes.image = Image(spec.width, spec.height, int(passes.names.size()));
  reads.add(file, part, passes.names, "color", frame, OIIO::TypeFloat, passes.image.pixels.data(),
            passes.image.channels);
}

}  // namespace

PassHeader readPassHeader(const AovLayout& layout, int frame) {
  if (!layout.passes || layout.color.pattern.empty()) return {};
  const std::string path = expandFramePattern(layout.color.pattern, frame);
  FileSet files(frame);
  OpenExr& file = files.get(path, "color");
  AovSource requiredColor = layout.color;
  requiredColor.channels.resize(std::min<std::size_t>(requiredColor.channels.size(), 3));
  const int part = findPart(file, requiredColor, "color", frame);
  const OIIO::ImageSpec& spec = file.parts[std::size_t(part)];
  return {passChannels(spec, layout), spec.width, spec.height};
}

FrameData readFrame(const AovLayout& layout, int frame, const CameraInputs& cameras,
                    const PassBandReceiver& passBands, int decodeThreads) {
  if (layout.color.pattern.empty()) {
    throw Error("no color file pattern given", {"", frame, ""});
  }
  requireChannelCount(layout.color, 3, 4, "color", frame);
  if (layout.depth) requireChannelCount(*layout.depth, 1, 1, "depth", frame);
  if (layout.motion) requireChannelCount(*layout.motion, 2, 2, "motion", frame);

  FrameData data;
  data.frame = frame;
  data.colorPath = expandFramePattern(layout.color.pattern, frame);

  FileSet files(frame);
  PartReads reads;
  OpenExr& colorFile = files.get(data.colorPath, "color");
  AovSource requiredColor = layout.color;  // alpha is optional (addColorRead)
  requiredColor.channels.resize(3);
  const int colorPart = findPart(colorFile, requiredColor, "color", frame);
  data.colorSpec = colorFile.parts[std::size_t(colorPart)];
  data.colorPart = colorPart;
  const int colorChannels =
      addColorRead(reads, colorFile, colorPart, layout.color, frame, data.color);
  data.window = rasterWindow(data.colorSpec);
  chooseCamera(data, cameras);
  if (layout.passes) {
    addPassesRead(reads, colorFile, colorPart, layout, frame, data.passes, passBands);
  } else {
    addPassthroughRead(reads, colorFile, colorPart, layout.passthrough, frame, data.passthrough);
  }

  const OpenExr* depthFile = nullptr;
  if (layout.depth) {
    OpenExr& file = files.get(aovPath(*layout.depth, data.colorPath, frame), "depth");
    const int part = findPart(file, *layout.depth, "depth", frame);
    requireSameWindow(file, part, data.colorSpec, data.colorPath, "depth", frame);
    data.depth = Image(data.colorSpec.width, data.colorSpec.height, 1);
    requireHalfOrFloat(file, part, layout.depth->channels, "depth", frame);
    reads.add(file, part, layout.depth->channels, "depth", frame, OIIO::TypeFloat,
              data.depth.pixels.data(), 1);
    depthFile = &file;
  }
  if (layout.motion) {
    OpenExr& file = files.get(aovPath(*layout.motion, data.colorPath, frame), "motion");
    const int part = findPart(file, *layout.motion, "motion", frame);
    requireSameWindow(file, part, data.colorSpec, data.colorPath, "motion", frame);
    data.motion = Image(data.colorSpec.width, data.colorSpec.height, 2);
    requireHalfOrFloat(file, part, layout.motion->channels, "motion", frame);
    reads.add(file, part, layout.motion->channels, "motion", frame, OIIO::TypeFloat,
              data.motion.pixels.data(), 2);
    data.motionPath = file.path;
  }

  reads.readAll(frame, decodeThreads);
  finishColor(data, colorChannels);
  if (depthFile) {
    if (layout.depthConvention.kind == DepthKind::Radial) {
      radialToPlanar(data.depth, pixelRayFor(data, layout.depthConvention, depthFile->path),
                     layout.depthConvention.noHitAbove);
    } else {
      convertDepth(data.depth, layout.depthConvention);
    }
  }
  if (layout.motion) {
    data.nonFiniteMotionValues = convertMotion(data.motion, layout.motionConvention, data.window);
  }
  return data;
}

}  // namespace taa::io
