#include "py_outputs.h"

#include <pybind11/stl.h>

#include <string>
#include <utility>

#include "io/output_completeness.h"
#include "io/stale_temp_files.h"

namespace py = pybind11;

namespace taa::python {

void registerOutputChecks(py::module_& module) {
  module.def(
      "check_output",
      [](const std::string& path, const std::string& expectedOptions) {
        io::OutputCheck check;
        {
          py::gil_scoped_release release;  // reads every pixel
          check = io::checkOutputComplete(path, expectedOptions);
        }
        return std::make_pair(check.complete, check.reason);
      },
      py::arg("path"), py::arg("expected_options") = "",
      R"doc(Whether an output frame is complete: (True, "") or (False, why).

Reads the whole file (every pixel of every part) and its taa:version and taa:options
attributes: a file cut short after it was written still opens, its pixels do not read.
expected_options: when given, taa:options must equal it.)doc");
  module.def(
      "remove_stale_temporaries",
      [](const std::string& outputPattern) {
        const io::StaleTemporaries stale = io::removeStaleTemporaries(outputPattern);
        return std::make_pair(stale.removed, stale.failed);
      },
      py::arg("output_pattern"),
      R"doc(Removes the temporaries that runs killed on this host left beside an output.

Frames being written (".NAME.taa-tmp-HOST-PID-N.exr") of output_pattern's frames and farm
scratch folders (".taa-farm-HOST-PID-*") whose process is gone. Returns (removed paths,
"path: reason" for those that could not be removed). Another host's are left alone.)doc");
  module.def("farm_scratch_prefix", &io::farmScratchPrefix,
             R"doc(".taa-farm-HOST-PID-": name a farm scratch folder with it (tempfile.mkdtemp's
prefix) so that remove_stale_temporaries can tell when its process is gone.)doc");
}

}  // namespace taa::python
