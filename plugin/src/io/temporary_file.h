// The one way taa creates a file it renames into place later: created exclusively, never
// through a symbolic link, under a name no one can guess. Anyone who can write the output
// folder could otherwise plant a link at a predictable temporary name and have taa overwrite
// the link's target (issue 25, defect 3).
#pragma once

#include <cstdio>
#include <filesystem>
#include <string>

namespace taa::io {

class TemporaryFile {
 public:
  // Creates ".<final name>.taa-tmp-<host>-<pid>-<16 random hex digits>.exr" beside
  // `finalPath` with O_CREAT | O_EXCL | O_NOFOLLOW (mode 0666 less the umask): a name already
  // taken, a link planted there included, is never opened; a new random name is tried instead.
  // Throws taa::Error naming the folder when none can be created.
  explicit TemporaryFile(const std::filesystem::path& finalPath);
  // Closes and removes the file unless it was committed.
  ~TemporaryFile();
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  const std::filesystem::path& path() const { return path_; }
  // The open file to write through (binary, positioned at 0).
  std::FILE* stream() const { return stream_; }

  // Flushes and closes the file, then renames it over `finalPath` (atomic on POSIX: readers
  // see the old file or the new one, a link at `finalPath` is replaced, never followed).
  // Throws taa::Error with the reason; the temporary is then removed.
  void commitAs(const std::filesystem::path& finalPath);

 private:
  std::filesystem::path path_;
  std::FILE* stream_ = nullptr;
  bool committed_ = false;
};

// 16 hex digits from the kernel's random source: a temporary's unguessable part.
std::string unguessableToken();

}  // namespace taa::io
