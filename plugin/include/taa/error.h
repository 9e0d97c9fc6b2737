// The one exception type of taa. It carries the context a user needs to find the problem:
// which file, which frame, which channel. Library code throws it and never prints or exits;
// faces (CLI, C ABI, plugins) catch it at their boundary.
#pragma once

#include <optional>
#include <stdexcept>
#include <string>

#include "taa/export.h"
#include "taa/version.h"

TAA_NAMESPACE_BEGIN

struct ErrorContext {
  std::string file{};        // path of the file involved, empty if none
  std::optional<int> frame{};  // frame number involved, if any
  std::string channel{};     // channel (or AOV) involved, empty if none
};

class TAA_API Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what, ErrorContext context = {});

  // The bare description, without the context suffix that what() carries.
  const std::string& description() const { return description_; }
  const ErrorContext& context() const { return context_; }

 private:
  std::string description_;
  ErrorContext context_;
};

// "<what> : <file> (frame N, channel C)", leaving out parts that are empty.
TAA_API std::string formatErrorMessage(const std::string& what, const ErrorContext& context);

TAA_NAMESPACE_END
