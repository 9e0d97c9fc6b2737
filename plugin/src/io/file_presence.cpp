#include "io/file_presence.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

namespace taa::io {

std::string fileAbsence(const std::string& path) {
  struct stat target {};
  if (::stat(path.c_str(), &target) == 0) {
    if (S_ISREG(target.st_mode)) return "";
    return S_ISDIR(target.st_mode) ? "a folder" : "not a regular file";
  }
  const int why = errno;
  if (why == ELOOP) return "a loop of symbolic links";
  struct stat link {};
  if (why == ENOENT && ::lstat(path.c_str(), &link) == 0 && S_ISLNK(link.st_mode)) {
    std::vector<char> to(std::size_t(link.st_size > 0 ? link.st_size : 255) + 1);
    const ssize_t n = ::readlink(path.c_str(), to.data(), to.size() - 1);
    const std::string where = n >= 0 ? std::string(to.data(), std::size_t(n)) : "?";
    return "a symbolic link to " + where + ", which does not exist";
  }
  return why == ENOENT ? "missing" : std::strerror(why);
}

}  // namespace taa::io
