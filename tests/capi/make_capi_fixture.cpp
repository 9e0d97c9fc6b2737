// Fixture for the C tests: renders a short moving_object sequence with the scene generator,
// resolves it with the C++ Resolver (the reference), and writes both as one raw file the C
// tests can read without an EXR library.
//   make_capi_fixture OUT_FILE
// Layout (native endianness): "TAAFIX01", int32 width, height, count; then per frame: int32
// frame, float32 color[w*h*4], depth[w*h], motion[w*h*2], reference[w*h*4], rows top first,
// all in internal conventions (depth +inf = no hit; motion y down, to the previous frame).
#include <cstdint>
#include <cstdio>
#include <exception>
#include <fstream>
#include <vector>

#include "gl/context.h"
#include "resolve/jitter.h"
#include "resolve/resolver.h"
#include "scenegen/scene_library.h"

namespace {

constexpr int kWidth = 48, kHeight = 32, kFirst = 1, kCount = 8;

void writeInt(std::ofstream& out, std::int32_t value) {
  out.write(reinterpret_cast<const char*>(&value), sizeof value);
}

void writeImage(std::ofstream& out, const taa::Image& image) {
  out.write(reinterpret_cast<const char*>(image.pixels.data()),
            std::streamsize(image.pixels.size() * sizeof(float)));
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: make_capi_fixture OUT_FILE\n");
    return 2;
  }
  try {
    auto scene = taa::scenes::makeScene("moving_object", kWidth, kHeight);
    taa::scenes::RenderSettings settings;
    settings.truthSamplesPerAxis = 1;  // the truth is not used here
    auto context = taa::gl::Context::create(taa::gl::Backend::Auto);
    taa::Resolver resolver(*context, taa::ResolveOptions{});

    std::ofstream out(argv[1], std::ios::binary);
    out.write("TAAFIX01", 8);
    writeInt(out, kWidth);
    writeInt(out, kHeight);
    writeInt(out, kCount);
    for (int frame = kFirst; frame < kFirst + kCount; ++frame) {
      const taa::scenes::SceneFrame rendered = scene->render(frame, settings);
      taa::ResolveInput input;
      input.color = &rendered.color;
      input.depth = &rendered.depth;
      input.motion = &rendered.motion;
      input.jitter = taa::frameJitter(frame, taa::JitterOptions{});
      const taa::Image reference = resolver.resolve(input);
      writeInt(out, frame);
      writeImage(out, rendered.color);
      writeImage(out, rendered.depth);
      writeImage(out, rendered.motion);
      writeImage(out, reference);
    }
    if (!out) throw std::runtime_error("cannot write the fixture file");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "make_capi_fixture: %s\n", e.what());
    return 1;
  }
  return 0;
}
