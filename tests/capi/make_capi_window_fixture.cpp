// Fixture for the C ABI's window-mode test: renders a short 3D sequence with a moving camera
// (rotate_yaw: camera matrices, depth and vectors, so window mode carries samples both by camera
// reprojection and along vectors), writes it as EXR files, runs the real taatool on them in
// window mode, and writes the frames as taatool read them, with taatool's outputs, as one raw
// file the C test reads without an EXR library.
//   make_capi_window_fixture TAATOOL OUT_FILE WORK_DIR
// Layout (native endianness): "TAAWIN01", int32 width, height, count, references; then per
// frame: int32 frame, float32 world_to_camera[16], world_to_ndc[16] (as stored in the header,
// row-major), color[w*h*4], depth[w*h], motion[w*h*2], then one RGBA output[w*h*4] per
// reference, in the order of kReferences below. Rows top first.
#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "scenegen/exr_output.h"
#include "scenegen/scene_library.h"

namespace {

namespace fs = std::filesystem;

constexpr int kWidth = 48, kHeight = 32, kFirst = 1, kCount = 8;

// taatool's arguments per reference; capi_window_test.c knows them by index.
const char* const kReferences[] = {
    "--mode window --window 2",
    "--mode window --window 4",
    "--mode window --window 2 --reset-frames 5",
};

struct ExrFile {
  std::vector<float> pixels;  // the named channels, interleaved
  std::vector<float> worldToCamera, worldToNdc;  // empty when the header has none
};

ExrFile readExr(const std::string& path, const std::vector<std::string>& names) {
  auto in = OIIO::ImageInput::open(path);
  if (!in) throw std::runtime_error("cannot open " + path + ": " + OIIO::geterror());
  const OIIO::ImageSpec& spec = in->spec();
  if (spec.width != kWidth || spec.height != kHeight) {
    throw std::runtime_error(path + " has an unexpected size");
  }
  std::vector<float> all(std::size_t(spec.width) * spec.height * spec.nchannels);
  if (!in->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data())) {
    throw std::runtime_error("cannot read " + path + ": " + in->geterror());
  }
  ExrFile file;
  const std::size_t pixels = std::size_t(spec.width) * spec.height;
  file.pixels.resize(pixels * names.size());
  for (std::size_t c = 0; c < names.size(); ++c) {
    const int source = spec.channelindex(names[c]);
    if (source < 0) throw std::runtime_error("no channel " + names[c] + " in " + path);
    for (std::size_t p = 0; p < pixels; ++p) {
      file.pixels[p * names.size() + c] = all[p * spec.nchannels + std::size_t(source)];
    }
  }
  auto matrix = [&](const char* name, std::vector<float>& out) {
    if (const OIIO::ParamValue* value = spec.find_attribute(name, OIIO::TypeMatrix44)) {
      const float* m = static_cast<const float*>(value->data());
      out.assign(m, m + 16);
    }
  };
  matrix("worldToCamera", file.worldToCamera);
  matrix("worldToNDC", file.worldToNdc);
  return file;
}

void writeInt(std::ofstream& out, std::int32_t value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

void writeFloats(std::ofstream& out, const std::vector<float>& values) {
  out.write(reinterpret_cast<const char*>(values.data()),
            std::streamsize(values.size() * sizeof(float)));
}

std::string shellQuoted(const fs::path& path) { return "'" + path.string() + "'"; }

std::string framePath(const fs::path& dir, const std::string& stem, int frame) {
  return taa::scenes::framePath(dir.string(), stem, frame);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) {
    std::fprintf(stderr, "usage: make_capi_window_fixture TAATOOL OUT_FILE WORK_DIR\n");
    return 2;
  }
  try {
    const std::string taatool = argv[1];
    const fs::path work = argv[3];
    fs::remove_all(work);
    auto scene = taa::scenes::makeScene("rotate_yaw", kWidth, kHeight);
    taa::scenes::RenderSettings settings;
    settings.truthSamplesPerAxis = 1;  // the truth is not used here
    for (int frame = kFirst; frame < kFirst + kCount; ++frame) {
      taa::scenes::writeFrame(scene->render(frame, settings), "rotate_yaw",
                              taa::scenes::OutputLayout::Separate, work.string());
    }
    const int references = int(std::size(kReferences));
    for (int r = 0; r < references; ++r) {
      const fs::path out = work / ("reference" + std::to_string(r));
      // $OCIO unset: the node's default is taa's shipped config, taatool's would be $OCIO's.
      const std::string command = "env -u OCIO " + shellQuoted(taatool) + " " +
                                  shellQuoted(work / "beauty.####.exr") + " --depth " +
                                  shellQuoted(work / "depth.####.exr") + " --motion " +
                                  shellQuoted(work / "motion.####.exr") + " -d float " +
                                  kReferences[r] + " -o " + shellQuoted(out / "out.####.exr") + " -q";
      if (std::system(command.c_str()) != 0) {
        throw std::runtime_error("taatool failed: " + command);
      }
    }

    std::ofstream out(argv[2], std::ios::binary);
    out.write("TAAWIN01", 8);
    for (int value : {kWidth, kHeight, kCount, references}) writeInt(out, value);
    for (int frame = kFirst; frame < kFirst + kCount; ++frame) {
      const ExrFile color = readExr(framePath(work, "beauty", frame), {"R", "G", "B", "A"});
      if (color.worldToCamera.empty() || color.worldToNdc.empty()) {
        throw std::runtime_error("frame " + std::to_string(frame) + " has no camera matrices");
      }
      writeInt(out, frame);
      writeFloats(out, color.worldToCamera);
      writeFloats(out, color.worldToNdc);
      writeFloats(out, color.pixels);
      writeFloats(out, readExr(framePath(work, "depth", frame), {"Z"}).pixels);
      writeFloats(out, readExr(framePath(work, "motion", frame), {"X", "Y"}).pixels);
      for (int r = 0; r < references; ++r) {
        const fs::path folder = work / ("reference" + std::to_string(r));
        writeFloats(out, readExr(framePath(folder, "out", frame), {"R", "G", "B", "A"}).pixels);
      }
    }
    if (!out) throw std::runtime_error("cannot write the fixture file");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_capi_window_fixture: %s\n", e.what());
    return 1;
  }
  return 0;
}
