// Measures the memory an instance of the OpenFX bundle holds while a host renders it on N
// threads, and what it gives back (docs/OFX.md): the bundle in the test host (tests/ofx), a
// window-mode instance on a synthetic clip of W x H frames (float RGBA, depth, motion), each
// thread rendering every N-th frame as a host's render threads do. Prints the process's
// resident memory (VmRSS) and its peak (VmHWM) after each step.
//   taa_ofx_memory [--size 1920x1080] [--threads 8] [--frames 16] [--bundle PATH]
// TAA_OFX_RENDER_NODES sets the plugin's node bound (default 2).
#include <malloc.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>
#include <thread>
#include <vector>

#include "test_host.h"

namespace {

using taa::Image;
using namespace taa::ofxtest;

// A /proc/self/status field in MB ("VmRSS", "VmHWM").
double statusMegabytes(const std::string& field) {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(field + ":", 0) == 0) return std::atof(line.c_str() + field.size() + 1) / 1024.0;
  }
  return 0.0;
}

void report(const std::string& step) {
  std::printf("%-44s VmRSS %7.0f MB   VmHWM %7.0f MB\n", step.c_str(), statusMegabytes("VmRSS"),
              statusMegabytes("VmHWM"));
  std::fflush(stdout);
}

// Frames of a clip: a pattern that moves (so every frame differs), `channels` per pixel.
ClipFrames makeClip(int width, int height, int channels, int frames, float base) {
  ClipFrames clip;
  for (int f = 1; f <= frames; ++f) {
    Image image(width, height, channels);
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        for (int c = 0; c < channels; ++c) {
          image.pixels[(std::size_t(y) * width + x) * channels + c] =
              base + float(((x + 3 * f) ^ (y * 7)) & 15) / 16.0f;
        }
      }
    }
    clip.frames[f] = std::move(image);
  }
  return clip;
}

int fail(const std::string& what) {
  std::cerr << "taa_ofx_memory: " << what << "\n";
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  int width = 1920, height = 1080, threads = 8, frames = 16;
  std::string bundle = TAA_OFX_BUNDLE_BINARY;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string option = argv[i], value = argv[i + 1];
    if (option == "--size" && std::sscanf(value.c_str(), "%dx%d", &width, &height) == 2) continue;
    if (option == "--threads") threads = std::atoi(value.c_str());
    else if (option == "--frames") frames = std::atoi(value.c_str());
    else if (option == "--bundle") bundle = value;
    else return fail("unknown option " + option);
  }
  if (width <= 0 || height <= 0 || threads <= 0 || frames <= 0) return fail("bad arguments");
  std::printf("%dx%d, %d threads, %d frames, TAA_OFX_RENDER_NODES=%s\n", width, height, threads,
              frames, std::getenv("TAA_OFX_RENDER_NODES") ? std::getenv("TAA_OFX_RENDER_NODES")
                                                          : "(unset: 2)");
  const ClipFrames color = makeClip(width, height, 4, frames, 0.1f);
  const ClipFrames depth = makeClip(width, height, 1, frames, 5.0f);
  const ClipFrames motion = makeClip(width, height, 3, frames, 0.0f);
  report("clips in memory (the host's frames)");

  TestHost host;
  if (const std::string error = host.load(bundle); !error.empty()) return fail(error);
  HostEffect descriptor, contextDescriptor;
  if (host.action(kOfxActionLoad, nullptr) != kOfxStatOK ||
      host.action(kOfxActionDescribe, &descriptor) != kOfxStatOK) {
    return fail("the bundle did not load");
  }
  PropertySet context;
  context.set(kOfxImageEffectPropContext, {std::string(kOfxImageEffectContextGeneral)});
  contextDescriptor.props = descriptor.props;
  if (host.action(kOfxImageEffectActionDescribeInContext, &contextDescriptor, &context) !=
      kOfxStatOK) {
    return fail("describe in context failed");
  }
  auto effect = host.makeInstance(contextDescriptor, kOfxImageEffectContextGeneral,
                                  {{"Source", &color}, {"Depth", &depth}, {"Motion", &motion}},
                                  OfxRectI{0, 0, width, height}, 1, frames);
  PropertySet preferences;
  if (host.action(kOfxActionCreateInstance, effect.get()) != kOfxStatOK ||
      host.clipPreferences(*effect, preferences) != kOfxStatOK) {
    return fail("the instance was not created");
  }
  report("bundle loaded, instance created");

  std::vector<std::thread> renderers;
  std::vector<int> failures(std::size_t(threads), 0);
  for (int t = 0; t < threads; ++t) {
    renderers.emplace_back([&, t] {
      for (int f = 1 + t; f <= frames; f += threads) {
        OutputImage output;
        if (host.render(*effect, f, output) != kOfxStatOK) ++failures[std::size_t(t)];
      }
    });
  }
  for (std::thread& thread : renderers) thread.join();
  for (int count : failures) {
    if (count) return fail("renders failed: " + host.messages().back());
  }
  report("rendered on " + std::to_string(threads) + " threads (peak: VmHWM)");
  host.action(kOfxImageEffectActionEndSequenceRender, effect.get());
  report("after EndSequenceRender");
  host.action(kOfxActionPurgeCaches, effect.get());
  report("after PurgeCaches");
  host.action(kOfxActionDestroyInstance, effect.get());
  report("after DestroyInstance");
  // What stays is freed memory glibc's arenas keep for the process, not held by taa: this
  // hands it back to show so.
  malloc_trim(0);
  report("after malloc_trim(0) (the allocator's free lists)");
  return 0;
}
