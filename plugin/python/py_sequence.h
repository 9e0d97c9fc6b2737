// taa.resolve_sequence: taatool's job (read EXRs, resolve, write atomically) with taatool's
// options as keyword arguments.
#pragma once

#include <pybind11/pybind11.h>

namespace taa::python {

void registerResolveSequence(pybind11::module_& module);

}  // namespace taa::python
