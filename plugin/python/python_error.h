// taa.Error, the Python exception of the module (a subclass of RuntimeError), carrying the
// library's message unchanged.
#pragma once

#include <stdexcept>
#include <string>

namespace taa::python {

class PythonError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace taa::python
