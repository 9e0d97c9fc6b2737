#include "io/stale_temp_files.h"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <climits>
#include <filesystem>
#include <optional>
#include <system_error>

#include "io/sequence_pattern.h"
#include "io/sequence_scan.h"

namespace taa::io {
namespace {

namespace fs = std::filesystem;

constexpr const char* kTempMarker = ".taa-tmp-";
constexpr const char* kFarmPrefix = ".taa-farm-";

// The writer named by a temporary.
struct Writer {
  std::string host;
  long long pid = 0;
};

bool allDigits(const std::string& text) {
  return !text.empty() && text.size() <= 10 &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) { return std::isdigit(c); });
}

// The name's unique part: random hex digits (io/temporary_file), or a counter in names written
// before temporaries were unguessable.
bool isUniquePart(const std::string& text) {
  return !text.empty() && text.size() <= 16 &&
         std::all_of(text.begin(), text.end(), [](unsigned char c) {
           return std::isdigit(c) || (c >= 'a' && c <= 'f');
         });
}

std::vector<std::string> splitOnDash(const std::string& text) {
  std::vector<std::string> fields;
  std::size_t begin = 0;
  for (std::size_t dash = text.find('-'); dash != std::string::npos;
       begin = dash + 1, dash = text.find('-', begin)) {
    fields.push_back(text.substr(begin, dash - begin));
  }
  fields.push_back(text.substr(begin));
  return fields;
}

// "<host>-<pid>" or, from before temporaries named their host, "<pid>" alone (this host).
std::optional<Writer> parseWriter(const std::vector<std::string>& fields) {
  if (fields.size() == 1 && allDigits(fields[0])) {
    return Writer{temporaryHostTag(), std::stoll(fields[0])};
  }
  if (fields.size() == 2 && !fields[0].empty() && allDigits(fields[1])) {
    return Writer{fields[0], std::stoll(fields[1])};
  }
  return std::nullopt;
}

// ".<name>.taa-tmp-<host>-<pid>-<unique>.exr" -> name and writer.
std::optional<std::pair<std::string, Writer>> parseTemporaryFile(const std::string& file) {
  const std::string extension = ".exr";
  if (file.size() < 2 + extension.size() || file[0] != '.' ||
      file.compare(file.size() - extension.size(), extension.size(), extension) != 0) {
    return std::nullopt;
  }
  const std::size_t marker = file.rfind(kTempMarker);
  if (marker == std::string::npos || marker < 2) return std::nullopt;
  const std::size_t fieldsBegin = marker + std::string(kTempMarker).size();
  if (fieldsBegin > file.size() - extension.size()) return std::nullopt;
  std::vector<std::string> fields =
      splitOnDash(file.substr(fieldsBegin, file.size() - extension.size() - fieldsBegin));
  if (fields.size() < 2 || !isUniquePart(fields.back())) return std::nullopt;
  fields.pop_back();
  const std::optional<Writer> writer = parseWriter(fields);
  if (!writer) return std::nullopt;
  return std::make_pair(file.substr(1, marker - 1), *writer);
}

// ".taa-farm-<host>-<pid>-<anything>" -> writer.
std::optional<Writer> parseFarmFolder(const std::string& folder) {
  const std::string prefix = kFarmPrefix;
  if (folder.compare(0, prefix.size(), prefix) != 0) return std::nullopt;
  std::vector<std::string> fields = splitOnDash(folder.substr(prefix.size()));
  if (fields.size() < 3) return std::nullopt;  // host, pid, a unique part
  fields.resize(2);
  return parseWriter(fields);
}

// Whether the writer may still be running: another host's always may.
bool mayBeRunning(const Writer& writer) {
  if (writer.host != temporaryHostTag()) return true;
  if (writer.pid <= 0 || writer.pid > INT_MAX) return false;
  if (writer.pid == ::getpid()) return true;
  // Signal 0 checks existence only; EPERM means it exists under another user.
  return ::kill(pid_t(writer.pid), 0) == 0 || errno == EPERM;
}

}  // namespace

std::string temporaryHostTag() {
  char name[256] = {};
  if (::gethostname(name, sizeof name - 1) != 0 || name[0] == '\0') return "localhost";
  std::string tag(name);
  tag.resize(std::min<std::size_t>(tag.size(), 64));
  for (char& c : tag) {
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '_') c = '_';
  }
  return tag;
}

std::string temporaryFileName(const std::string& finalName, const std::string& unique) {
  return "." + finalName.substr(0, 200) + kTempMarker + temporaryHostTag() + "-" +
         std::to_string(::getpid()) + "-" + unique + ".exr";
}

std::string farmScratchPrefix() {
  return kFarmPrefix + temporaryHostTag() + "-" + std::to_string(::getpid()) + "-";
}

StaleTemporaries removeStaleTemporaries(const std::string& outputPattern) {
  StaleTemporaries result;
  if (outputPattern.empty()) return result;
  const fs::path first = expandFramePattern(outputPattern, 1);
  if (first.parent_path() != fs::path(expandFramePattern(outputPattern, 2)).parent_path()) {
    return result;  // the folder changes with the frame
  }
  const fs::path folder = first.parent_path().empty() ? fs::path(".") : first.parent_path();
  const std::string namePattern = fs::path(outputPattern).filename().string();
  const bool sequence = hasFramePlaceholder(namePattern);
  auto isOutputName = [&](const std::string& name) {
    // Temporaries carry the first 200 bytes of the output's name.
    if (!sequence) return name == namePattern.substr(0, 200);
    return name.size() < 200 ? frameOfFileName(namePattern, name).has_value() : false;
  };

  std::error_code ec;
  fs::directory_iterator entries(folder, ec);
  if (ec) return result;
  for (; entries != fs::directory_iterator(); entries.increment(ec)) {
    if (ec) break;
    const std::string name = entries->path().filename().string();
    std::optional<Writer> writer;
    if (const auto temporary = parseTemporaryFile(name)) {
      if (isOutputName(temporary->first)) writer = temporary->second;
    } else if (entries->is_directory(ec)) {
      writer = parseFarmFolder(name);
    }
    if (!writer || mayBeRunning(*writer)) continue;
    std::error_code removeError;
    fs::remove_all(entries->path(), removeError);
    if (removeError) {
      result.failed.push_back(entries->path().string() + ": " + removeError.message());
    } else {
      result.removed.push_back(entries->path().string());
    }
  }
  return result;
}

}  // namespace taa::io
