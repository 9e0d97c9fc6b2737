#include "yardstick/scene_cache.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "taa/error.h"
#include "yardstick/process.h"

namespace taa::yardstick {
namespace fs = std::filesystem;
namespace {

// FNV-1a over a file's bytes. A content hash rather than a time: relinking the generator
// after unrelated library changes leaves it byte-identical, and the scenes stay cached.
std::uint64_t contentHash(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::uint64_t hash = 1469598103934665603ull;
  char buffer[65536];
  while (file.read(buffer, sizeof buffer) || file.gcount() > 0) {
    for (std::streamsize k = 0; k < file.gcount(); ++k) {
      hash = (hash ^ static_cast<unsigned char>(buffer[k])) * 1099511628211ull;
    }
  }
  return hash;
}

// What the scene in a folder was made from: the generator binary's content and the request.
std::string stampText(const std::string& scenegen, const SceneRequest& r) {
  std::ostringstream text;
  text << "generator " << std::hex << contentHash(scenegen) << std::dec << "\n"
       << "scene " << r.scene << " frames " << r.firstFrame << "-" << r.lastFrame << " size "
       << r.width << "x" << r.height << " truth " << r.truthSamples << "\n";
  return text.str();
}

std::string readAll(const fs::path& path) {
  std::ifstream file(path);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

}  // namespace

bool ensureScene(const std::string& scenegen, const SceneRequest& request, const std::string& dir,
                 const std::string& logPath) {
  const fs::path stamp = fs::path(dir) / "stamp.txt";
  const std::string wanted = stampText(scenegen, request);
  if (fs::exists(stamp) && readAll(stamp) == wanted) return false;

  std::error_code ec;
  fs::remove_all(dir, ec);
  fs::create_directories(dir, ec);
  if (ec) throw Error("cannot create the scene folder: " + ec.message(), {dir});
  const std::vector<std::string> command = {
      scenegen, "--scene", request.scene, "--frames",
      std::to_string(request.firstFrame) + "-" + std::to_string(request.lastFrame), "--size",
      std::to_string(request.width) + "x" + std::to_string(request.height), "--layout",
      "separate", "--truth-samples", std::to_string(request.truthSamples), "--out", dir};
  if (runProcess(command, logPath) != 0) {
    throw Error("taa-scenegen failed (see " + logPath + "): " + commandLine(command));
  }
  std::ofstream(stamp) << wanted;
  return true;
}

}  // namespace taa::yardstick
