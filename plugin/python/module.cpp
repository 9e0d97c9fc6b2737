// The Python module `taa`: resolve_sequence (whole EXR sequences, as taatool), Node (numpy
// arrays frame by frame, through the C ABI) and the output checks of resumable steps
// (check_output, remove_stale_temporaries). Errors raise taa.Error with the library's message.
#include <pybind11/pybind11.h>

#include "py_node.h"
#include "py_outputs.h"
#include "py_sequence.h"
#include "python_error.h"
#include "taa/taa.h"

PYBIND11_MODULE(taa, module) {
  module.doc() = "taa: temporal anti-aliasing resolve for EXR AOV sequences";
  pybind11::register_exception<taa::python::PythonError>(module, "Error", PyExc_RuntimeError);
  module.attr("__version__") = taa_version_string();
  module.attr("ABI_VERSION") = taa_abi_version();
  taa::python::registerResolveSequence(module);
  taa::python::registerNode(module);
  taa::python::registerOutputChecks(module);
}
