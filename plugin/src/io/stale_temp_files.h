// Temporary files that outlive their writer. Outputs are written into a temporary beside the
// target and renamed (io/exr_writer.h); a farm step of one's own may resolve into a scratch folder
// beside the output (taa.farm_scratch_prefix in Python; taa-farm needs none: its pre-roll is
// never written). A writer killed before its rename (SIGKILL, a node that lost power)
// leaves them behind. Their names carry the writer's host and process id, so a later run over
// the same output can tell the dead ones from those of a run still going:
//   .<file name>.taa-tmp-<host>-<pid>-<random>.exr   a frame being written (io/temporary_file)
//   .taa-farm-<host>-<pid>-<anything>/          a farm task's scratch folder
// Only temporaries of this host whose process is gone are removed: another host's process
// cannot be checked from here (on a shared file system its run may still be going).
#pragma once

#include <string>
#include <vector>

namespace taa::io {

// This host's name as temporaries carry it: letters, digits, '.' and '_' only ('-' separates
// the name's fields), at most 64 characters.
std::string temporaryHostTag();

// ".<finalName>.taa-tmp-<host>-<pid>-<unique>.exr" (finalName cut to 200 bytes, so the whole
// stays within a file system's 255; `unique` at most 16 hex digits).
std::string temporaryFileName(const std::string& finalName, const std::string& unique);

// ".taa-farm-<host>-<pid>-": the prefix of a farm scratch folder made by this process.
std::string farmScratchPrefix();

struct StaleTemporaries {
  std::vector<std::string> removed;  // paths removed
  std::vector<std::string> failed;   // stale, but could not be removed: "path: reason"
};

// In the folder of `outputPattern`'s frames: removes the temporary files of the pattern's frames
// and the farm scratch folders whose writer (this host, that pid) is no longer running. Names
// written before temporaries carried a host (".<name>.taa-tmp-<pid>-<n>.exr") count as this
// host's. A pattern whose folder changes with the frame is not searched. Never throws.
StaleTemporaries removeStaleTemporaries(const std::string& outputPattern);

}  // namespace taa::io
