#pragma once
// `landsim.Image`: one rendered image in memory. Its layers are numpy arrays over the film's
// own planes (read-only, no copy), named as the EXR names its channels, so an array equals
// the channel `landsim render` writes bit for bit.
#include <pybind11/pybind11.h>

#include "scenes/image_set/image_set.h"

namespace landsim::python {

void bind_image(pybind11::module_& m);

}  // namespace landsim::python
