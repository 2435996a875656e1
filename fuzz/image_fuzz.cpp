// An image through the image module (OpenImageIO): object and ground textures, and
// crosscheck's reference (header probe first, then the pixels). The module finds the format
// by content; the input's first byte picks the file's name (PNG, EXR, TIFF or JPEG) and
// whether 8-bit values are linearised.
#include "fuzz/fuzz_input.h"
#include "renderer/output/image_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  static const char* const kNames[] = {"image.png", "image.exr", "image.tif", "image.jpg"};
  const auto file = landsim::fuzz::input_file(data + 1, size - 1, kNames[data[0] % 4]);
  const landsim::renderer::ImageIo& io = landsim::renderer::image_io();
  int width = 0, height = 0, channels = 0;
  std::string error;
  io.probe(file.string(), width, height, channels, error);
  landsim::renderer::FloatImage image;
  io.read(file.string(), data[0] % 8 < 4, image, error);
  return 0;
}
