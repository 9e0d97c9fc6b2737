#include "gl/dynamic_library.h"

#include <dlfcn.h>

#include <utility>

#include "taa/error.h"

namespace taa::gl {

DynamicLibrary DynamicLibrary::open(const std::vector<std::string>& candidates) {
  std::string tried, reasons;
  for (const std::string& candidate : candidates) {
    // RTLD_NODELETE: GL drivers (Mesa, LLVM) are not safe to unload and load again within one
    // process, and a later context would do exactly that.
    void* handle = dlopen(candidate.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (handle) return DynamicLibrary(handle, candidate);
    const char* reason = dlerror();
    tried += (tried.empty() ? "" : ", ") + candidate;
    reasons += std::string(reasons.empty() ? "" : "; ") + (reason ? reason : "unknown reason");
  }
  if (candidates.empty()) throw Error("cannot load a shared library: no candidate names given");
  throw Error("cannot load " + tried + " (" + reasons + ")");
}

DynamicLibrary::~DynamicLibrary() { close(); }

DynamicLibrary::DynamicLibrary(DynamicLibrary&& other) noexcept
    : handle_(std::exchange(other.handle_, nullptr)), name_(std::move(other.name_)) {}

DynamicLibrary& DynamicLibrary::operator=(DynamicLibrary&& other) noexcept {
  if (this != &other) {
    close();
    handle_ = std::exchange(other.handle_, nullptr);
    name_ = std::move(other.name_);
  }
  return *this;
}

void DynamicLibrary::close() noexcept {
  if (handle_) dlclose(handle_);
  handle_ = nullptr;
}

void* DynamicLibrary::symbol(const char* name) const {
  return handle_ ? dlsym(handle_, name) : nullptr;
}

void* DynamicLibrary::requireSymbol(const char* name) const {
  void* address = symbol(name);
  if (!address) {
    throw Error(std::string("symbol ") + name + " not found in " +
                (name_.empty() ? std::string("an unloaded library") : name_));
  }
  return address;
}

}  // namespace taa::gl
