// Blender makes a session folder (blender_XXXXXX) under $TMPDIR, or /tmp without it, and leaves
// it behind when a script ends it: the tests point TMPDIR at a folder of their own program's
// (TAA_TEST_TMPDIR) before they run Blender, so nothing of theirs is left in /tmp.
#pragma once

#include <cstdlib>
#include <filesystem>

namespace taa::test {

inline void keepBlendersTemporaryFilesInTheTestFolder() {
  const std::filesystem::path folder = std::filesystem::path(TAA_TEST_TMPDIR) / "blender-tmp";
  std::filesystem::create_directories(folder);
  setenv("TMPDIR", folder.c_str(), 1);
}

}  // namespace taa::test
