// Checks of a job's outputs on disk for steps that resume it (a farm step of one's own; taa-farm
// does the same in C++): taa.check_output (is a frame complete?), taa.remove_stale_temporaries
// and taa.farm_scratch_prefix (temporaries of dead runs).
#pragma once

#include <pybind11/pybind11.h>

namespace taa::python {

void registerOutputChecks(pybind11::module_& module);

}  // namespace taa::python
