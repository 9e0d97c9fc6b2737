#include "gl/pass_profile.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <mutex>

namespace taa::gl {
namespace {

std::mutex& profileMutex() {
  static std::mutex mutex;
  return mutex;
}

std::vector<PassTime>& profileTable() {
  static std::vector<PassTime> table;
  return table;
}

}  // namespace

bool passProfileOn() {
  static const bool on = [] {
    const char* value = std::getenv("TAA_GL_PROFILE");
    return value != nullptr && *value != '\0' && std::strcmp(value, "0") != 0;
  }();
  return on;
}

void recordPassTime(const char* pass, double milliseconds) {
  const std::lock_guard<std::mutex> lock(profileMutex());
  std::vector<PassTime>& table = profileTable();
  for (PassTime& entry : table) {
    if (entry.pass == pass) {
      ++entry.draws;
      entry.milliseconds += milliseconds;
      return;
    }
  }
  table.push_back(PassTime{pass, 1, milliseconds});
}

std::vector<PassTime> passProfile() {
  const std::lock_guard<std::mutex> lock(profileMutex());
  return profileTable();
}

std::string passProfileText() {
  const std::vector<PassTime> table = passProfile();
  double total = 0.0;
  for (const PassTime& entry : table) total += entry.milliseconds;
  std::string text;
  char line[256];
  for (const PassTime& entry : table) {
    std::snprintf(line, sizeof line, "%-40s %6ld draws %11.1f ms %9.2f ms each %5.1f %%\n",
                  entry.pass.c_str(), entry.draws, entry.milliseconds,
                  entry.milliseconds / double(entry.draws), 100.0 * entry.milliseconds / total);
    text += line;
  }
  if (!table.empty()) {
    std::snprintf(line, sizeof line, "%-40s %6s       %11.1f ms\n", "all passes", "", total);
    text += line;
  }
  return text;
}

}  // namespace taa::gl
