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
  // The message may name a file whose name is not UTF-8: its bytes are kept as \xNN escapes
  // instead of turning taa.Error into a UnicodeDecodeError.
  static pybind11::exception<taa::python::PythonError> error(module, "Error", PyExc_RuntimeError);
  pybind11::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const taa::python::PythonError& e) {
      const std::string what = e.what();
      pybind11::object message = pybind11::reinterpret_steal<pybind11::object>(
          PyUnicode_DecodeUTF8(what.data(), Py_ssize_t(what.size()), "backslashreplace"));
      PyErr_SetObject(error.ptr(), message.ptr());
    }
  });
  module.attr("__version__") = taa_version_string();
  module.attr("ABI_VERSION") = taa_abi_version();
  taa::python::registerResolveSequence(module);
  taa::python::registerNode(module);
  taa::python::registerOutputChecks(module);
}
