// taa.Node: a C ABI node (taa.h) resolving numpy arrays frame by frame.
#pragma once

#include <pybind11/pybind11.h>

namespace taa::python {

void registerNode(pybind11::module_& module);

}  // namespace taa::python
