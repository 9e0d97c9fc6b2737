// A shared library opened at run time with dlopen. taa loads libEGL and libOSMesa this way so
// that a machine missing one of them can still use the other back end.
#pragma once

#include <string>
#include <vector>

namespace taa::gl {

class DynamicLibrary {
 public:
  DynamicLibrary() = default;
  // Opens the first of `candidates` (sonames or paths) that loads. Throws taa::Error naming
  // every candidate tried and the loader's reason for each.
  static DynamicLibrary open(const std::vector<std::string>& candidates);

  ~DynamicLibrary();
  DynamicLibrary(DynamicLibrary&& other) noexcept;
  DynamicLibrary& operator=(DynamicLibrary&& other) noexcept;
  DynamicLibrary(const DynamicLibrary&) = delete;
  DynamicLibrary& operator=(const DynamicLibrary&) = delete;

  // The symbol's address, or nullptr if the library does not export it.
  void* symbol(const char* name) const;
  // The symbol's address; throws taa::Error naming the symbol and the library if it is missing.
  void* requireSymbol(const char* name) const;

  // Typed form of requireSymbol for function pointers: lib.function<PFNEGLBINDAPIPROC>("...").
  template <typename FunctionPointer>
  FunctionPointer function(const char* name) const {
    return reinterpret_cast<FunctionPointer>(requireSymbol(name));
  }

  const std::string& name() const { return name_; }  // the candidate that loaded
  explicit operator bool() const { return handle_ != nullptr; }

 private:
  DynamicLibrary(void* handle, std::string name) : handle_(handle), name_(std::move(name)) {}
  void close() noexcept;

  void* handle_ = nullptr;
  std::string name_;
};

}  // namespace taa::gl
