#pragma once
// `landsim.render`, `landsim.render_set` and `landsim.info`: the render library
// (scenes/image_set/image_set.h) called as `landsim render` and `landsim info` call it.
#include <pybind11/pybind11.h>

namespace landsim::python {

void bind_render(pybind11::module_& m);

}  // namespace landsim::python
