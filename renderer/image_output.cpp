#include "renderer/image_output.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <cmath>
#include <stdexcept>

#include "core/atomic_file.h"

namespace landsim::renderer {
namespace {

void add_slice(Imf::FrameBuffer& fb, const char* name, const std::vector<float>& plane, int stride,
               int offset, int width) {
  // OpenEXR's Slice takes a non-const pointer even for writing.
  char* base = reinterpret_cast<char*>(const_cast<float*>(plane.data() + offset));
  fb.insert(name, Imf::Slice(Imf::FLOAT, base, sizeof(float) * static_cast<std::size_t>(stride),
                             sizeof(float) * static_cast<std::size_t>(stride) *
                                 static_cast<std::size_t>(width)));
}

}  // namespace

void write_exr(const Film& film, const std::filesystem::path& path, const ImageMetadata& metadata) {
  AtomicFile out(path);
  Imf::Header header(film.width(), film.height());
  header.compression() = Imf::ZIP_COMPRESSION;
  for (const char* name : {"R", "G", "B", "Z", "N.X", "N.Y", "N.Z"}) {
    header.channels().insert(name, Imf::Channel(Imf::FLOAT));
  }
  for (const auto& [key, value] : metadata) {
    header.insert("landsim/" + key, Imf::StringAttribute(value));
  }
  Imf::FrameBuffer fb;
  const int w = film.width();
  add_slice(fb, "R", film.rgb_data(), 3, 0, w);
  add_slice(fb, "G", film.rgb_data(), 3, 1, w);
  add_slice(fb, "B", film.rgb_data(), 3, 2, w);
  add_slice(fb, "Z", film.depth_data(), 1, 0, w);
  add_slice(fb, "N.X", film.normal_data(), 3, 0, w);
  add_slice(fb, "N.Y", film.normal_data(), 3, 1, w);
  add_slice(fb, "N.Z", film.normal_data(), 3, 2, w);
  {
    Imf::OutputFile file(out.temp_path().c_str(), header);
    file.setFrameBuffer(fb);
    file.writePixels(film.height());
  }  // closed before the rename
  out.commit();
}

void write_preview_png(const Film& film, const std::filesystem::path& path, double exposure_ev) {
  AtomicFile out(path);
  const OIIO::ImageSpec spec(film.width(), film.height(), 3, OIIO::TypeDesc::FLOAT);
  const OIIO::ImageBuf linear(spec, const_cast<float*>(film.rgb_data().data()));
  const float gain = static_cast<float>(std::exp2(exposure_ev));
  OIIO::ImageBuf exposed = OIIO::ImageBufAlgo::mul(linear, gain);
  OIIO::ImageBuf display = OIIO::ImageBufAlgo::colorconvert(exposed, "linear", "sRGB");
  if (display.has_error() ||
      !display.write(out.temp_path().string(), OIIO::TypeDesc::UINT8, "png")) {
    throw std::runtime_error("writing " + path.string() + " failed: " + display.geterror());
  }
  out.commit();
}

}  // namespace landsim::renderer
