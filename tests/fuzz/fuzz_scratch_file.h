// The file a fuzz target writes each input to before the code under test reads it back. It
// lives in a directory of its own made by mkdtemp under $TMPDIR (not a name another user of a
// shared /tmp could guess and plant a link at), and the directory goes when the process exits
// normally (libFuzzer's end of -max_total_time included), so a run leaves nothing behind.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <unistd.h>

class FuzzScratchFile {
 public:
  explicit FuzzScratchFile(const std::string& name) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/taa-fuzz-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (!::mkdtemp(buffer.data())) throw std::runtime_error("mkdtemp failed for " + pattern);
    directory_ = buffer.data();
    path_ = directory_ + "/" + name;
  }
  ~FuzzScratchFile() {
    ::unlink(path_.c_str());
    ::rmdir(directory_.c_str());
  }
  FuzzScratchFile(const FuzzScratchFile&) = delete;
  FuzzScratchFile& operator=(const FuzzScratchFile&) = delete;

  const std::string& path() const { return path_; }

  // Replaces the file's contents with `size` bytes.
  void write(const void* data, std::size_t size) const {
    std::ofstream(path_, std::ios::binary | std::ios::trunc)
        .write(static_cast<const char*>(data), std::streamsize(size));
  }

 private:
  std::string directory_;
  std::string path_;
};
