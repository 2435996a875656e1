#include "renderer/image_io.h"

#include "core/module_loader.h"

namespace landsim::renderer {

const ImageIo& image_io() { return module_table<ImageIo>("images", kImageIoSymbol); }

}  // namespace landsim::renderer
