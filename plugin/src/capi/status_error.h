// An error with the C ABI status it maps to. Thrown inside plugin/src/capi and caught at the
// boundary (taa_node.cpp), where it becomes the call's return value and last-error message.
#pragma once

#include <stdexcept>
#include <string>

#include "taa/taa.h"

namespace taa::capi {

class StatusError : public std::runtime_error {
 public:
  StatusError(taa_status status, const std::string& what)
      : std::runtime_error(what), status_(status) {}
  taa_status status() const { return status_; }

 private:
  taa_status status_;
};

}  // namespace taa::capi
