// Running the taatool binary from the end-to-end tests, and checking how it failed.
#pragma once

#include <OpenImageIO/imageio.h>

#include <filesystem>
#include <string>
#include <vector>

namespace taa::test {

struct ToolRun {
  int exitCode = -1;  // -1 when taatool did not exit normally
  std::string out, err;
};

// A fresh folder for the running test: <root>/<test name>, emptied first.
std::filesystem::path freshTestFolderIn(const std::filesystem::path& root);
#ifdef TAA_TEST_TMPDIR
// The same under this test program's TAA_TEST_TMPDIR (taa_add_gtest defines it). Inline, so the
// folder is the including program's own: the runner is compiled once, into a library every
// program links.
inline std::filesystem::path freshTestFolder() { return freshTestFolderIn(TAA_TEST_TMPDIR); }
#endif

// The taatool the tests run: TAA_TAATOOL_PATH, unless the environment variable of that name
// gives another (to run a suite against another build).
std::string taatoolPath();

// Runs taatool with `args` and no standard input; stdout and stderr are captured through files
// in `scratch`.
ToolRun runTaatool(const std::vector<std::string>& args, const std::filesystem::path& scratch);
// The same for any program; the variables named in `unset` are taken out of its environment
// (the rest of this process's environment is passed on).
ToolRun runProgram(const std::string& program, const std::vector<std::string>& args,
                   const std::filesystem::path& scratch,
                   const std::vector<std::string>& unset = {});

// Expects a failure as taatool reports one: exit status 1, stderr's last line starting
// "taatool ERROR: " (progress lines may come before it), and each of `fragments` in it.
void expectToolError(const ToolRun& run, const std::vector<std::string>& fragments);

// Frames [first, last] of the scene generator's `scene` at width x height written into `folder`
// as separate files: beauty.####.exr (half RGBA), depth.####.exr, motion.####.exr.
void writeSeparateFrames(const std::filesystem::path& folder, int first, int last, int width = 64,
                         int height = 40, const std::string& scene = "moving_object");

// taatool's arguments for writeSeparateFrames' files in `in`, output to `outPattern`.
std::vector<std::string> separateFileArgs(const std::filesystem::path& in,
                                          const std::filesystem::path& outPattern);

// "stem.0007.exr" for frame 7: the names writeSeparateFrames and the tests' outputs use.
std::string frameName(const std::string& stem, int frame);

// An EXR's header and every channel as float, pixels interleaved.
struct Exr {
  OIIO::ImageSpec spec;
  std::vector<float> pixels;
  // Pixel `pixel`'s value of `channel` (which must exist).
  float at(std::size_t pixel, const std::string& channel) const {
    return pixels[pixel * std::size_t(spec.nchannels) + std::size_t(spec.channelindex(channel))];
  }
};

// The file at `path`; a test failure (and an empty Exr) when it cannot be read.
Exr readExr(const std::filesystem::path& path);

}  // namespace taa::test
