#include "renderer/output/image_io.h"

#include <atomic>

#include "core/module_loader.h"

namespace landsim::renderer {

namespace {
std::atomic<bool> g_loaded{false};
}  // namespace

const ImageIo& image_io() {
  const ImageIo& table = module_table<ImageIo>("images", kImageIoSymbol);
  g_loaded = true;
  return table;
}

bool image_io_loaded() { return g_loaded; }

}  // namespace landsim::renderer
