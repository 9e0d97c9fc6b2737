// Helpers for the I/O tests: a fresh scratch folder per test, and small hand-made image files.
#pragma once

#include <OpenImageIO/imageio.h>

#include <functional>
#include <string>
#include <vector>

#include "taa/error.h"

namespace taa::test {

// An empty folder for the running test: <root>/<suite>.<test>, wiped first.
std::string scratchFolderIn(const std::string& root);
#ifdef TAA_TEST_TMPDIR
// The same under this test program's TAA_TEST_TMPDIR (taa_add_gtest defines it). Inline, so the
// folder is the including program's own: the helpers are compiled once, into a library every
// program links.
inline std::string scratchFolder() { return scratchFolderIn(TAA_TEST_TMPDIR); }
#endif

// A float spec of width x height with the given channel names, data window at the origin.
OIIO::ImageSpec makeSpec(int width, int height, const std::vector<std::string>& channels);

// Writes `pixels` (interleaved in the spec's channel order, rows top first) with the format
// the file name implies. Throws std::runtime_error on failure.
void writeImage(const std::string& path, const OIIO::ImageSpec& spec,
                const std::vector<float>& pixels);

// Reads all channels of subimage 0 as float; `spec` receives the file's header.
std::vector<float> readImage(const std::string& path, OIIO::ImageSpec& spec);

// Writes `text` to `path` as is.
void writeTextFile(const std::string& path, const std::string& text);

// Names in `folder` (not recursive), sorted.
std::vector<std::string> listFolder(const std::string& folder);

// True when `part` occurs in `text` (error-message checks).
bool contains(const std::string& text, const std::string& part);

// The taa::Error that `run` throws; a test failure (and an empty error) when it throws none.
Error errorOf(const std::function<void()>& run);

}  // namespace taa::test
