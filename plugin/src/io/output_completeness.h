// Whether an output frame on disk is complete, for steps that resume a job and redo only what is
// missing (taa-farm, farm/run_chunk.cpp). Outputs are renamed into place whole, but a file can be
// cut short afterwards (a copy onto a full disk, a sync that died) and its header still opens:
// only reading every pixel of every part shows it. Frames taa wrote also carry its metadata,
// taa:version and taa:options (the resolve options, resolve/sequence_job.cpp).
#pragma once

#include <string>

namespace taa::io {

struct OutputCheck {
  bool complete = false;
  std::string reason;  // why not, for logs: "missing", "no taa:options attribute", ...
};

// Reads the whole file at `path`: every part's pixels, and the taa:version and taa:options
// attributes of its first part. With `expectedOptions` non-empty, taa:options must equal it (a
// frame resolved with other options is not this job's output). Never throws.
OutputCheck checkOutputComplete(const std::string& path, const std::string& expectedOptions = "");

}  // namespace taa::io
