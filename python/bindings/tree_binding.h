#pragma once
// `landsim.tree`: one tree of a species file as numpy arrays (the mesh `landsim tree --obj`
// writes), each face tagged with its Weber & Penn group (trunk, level1, level2, level3plus,
// leaves: the parts range-aware degradation drops in turn).
#include <pybind11/pybind11.h>

namespace landsim::python {

void bind_tree(pybind11::module_& m);

}  // namespace landsim::python
