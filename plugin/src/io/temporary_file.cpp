#include "io/temporary_file.h"

#include <fcntl.h>
#include <sys/random.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

#include "io/stale_temp_files.h"
#include "taa/error.h"

namespace taa::io {

namespace fs = std::filesystem;

std::string unguessableToken() {
  unsigned char bytes[8];
  std::size_t got = 0;
  while (got < sizeof bytes) {
    const ssize_t n = ::getrandom(bytes + got, sizeof bytes - got, 0);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) throw Error(std::string("cannot read random bytes: ") + std::strerror(errno));
    got += std::size_t(n);
  }
  static const char kHex[] = "0123456789abcdef";
  std::string token;
  for (unsigned char b : bytes) {
    token += kHex[b >> 4];
    token += kHex[b & 15];
  }
  return token;
}

TemporaryFile::TemporaryFile(const fs::path& finalPath) {
  const fs::path folder = finalPath.parent_path();
  int lastErrno = 0;
  // A taken name (by chance, or a link planted by someone guessing) costs a retry, nothing more.
  for (int attempt = 0; attempt < 16; ++attempt) {
    const fs::path candidate =
        folder / temporaryFileName(finalPath.filename().string(), unguessableToken());
    const int fd = ::open(candidate.c_str(),
                          O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
    if (fd < 0) {
      lastErrno = errno;
      if (errno == EEXIST || errno == ELOOP || errno == EINTR) continue;
      break;
    }
    stream_ = ::fdopen(fd, "wb");
    if (!stream_) {
      lastErrno = errno;
      ::close(fd);
      ::unlink(candidate.c_str());
      break;
    }
    path_ = candidate;
    return;
  }
  throw Error("cannot create a temporary file in " +
                  (folder.empty() ? std::string(".") : folder.string()) + ": " +
                  std::strerror(lastErrno),
              {finalPath.string(), std::nullopt, ""});
}

TemporaryFile::~TemporaryFile() {
  if (stream_) std::fclose(stream_);
  if (!committed_) ::unlink(path_.c_str());  // a link put there since is removed, not followed
}

void TemporaryFile::commitAs(const fs::path& finalPath) {
  const ErrorContext context{finalPath.string(), std::nullopt, ""};
  const bool flushed = std::fflush(stream_) == 0;
  const int flushErrno = errno;
  const bool closed = std::fclose(stream_) == 0;
  const int closeErrno = errno;
  stream_ = nullptr;
  if (!flushed || !closed) {
    throw Error("cannot finish writing: " + std::string(std::strerror(flushed ? closeErrno
                                                                              : flushErrno)),
                context);
  }
  if (std::rename(path_.c_str(), finalPath.c_str()) != 0) {
    throw Error("cannot move the written file into place: " + std::string(std::strerror(errno)),
                context);
  }
  committed_ = true;
}

}  // namespace taa::io
