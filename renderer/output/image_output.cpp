#include "renderer/output/image_output.h"

#include "renderer/output/exposure.h"

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfOutputFile.h>
#include <OpenEXR/ImfStandardAttributes.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenEXR/ImfThreading.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <thread>

#include "core/atomic_file.h"
#include "renderer/output/image_io.h"

namespace landsim::renderer {
namespace {

// OpenEXR's worker threads, one per core, started once.
int exr_threads() {
  static const int threads = [] {
    const int n = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    Imf::setGlobalThreadCount(n);
    return n;
  }();
  return threads;
}

// Scene-linear Rec.709 in, the sRGB display out (the sRGB curve: exponent 2.4, offset 0.055).
constexpr const char* kOcioConfig = R"(ocio_profile_version: 2

roles:
  default: linear_rec709
  scene_linear: linear_rec709
  color_picking: srgb_display

file_rules:
  - !<Rule> {name: Default, colorspace: default}

displays:
  sRGB:
    - !<View> {name: Standard, colorspace: srgb_display}

active_displays: [sRGB]
active_views: [Standard]

colorspaces:
  - !<ColorSpace>
    name: linear_rec709
    family: linear
    description: landsim radiance, linear Rec.709 primaries, D65
    isdata: false

  - !<ColorSpace>
    name: srgb_display
    family: display
    description: sRGB display (IEC 61966-2-1 transfer), Rec.709 primaries
    isdata: false
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
)";

template <typename T>
void add_slice(Imf::FrameBuffer& fb, const char* name, Imf::PixelType type, std::vector<T>& plane,
               int stride, int offset, int width) {
  char* base = reinterpret_cast<char*>(plane.data() + offset);
  fb.insert(name, Imf::Slice(type, base, sizeof(T) * static_cast<std::size_t>(stride),
                             sizeof(T) * static_cast<std::size_t>(stride) *
                                 static_cast<std::size_t>(width)));
}

struct Channel {
  const char* name;
  bool id;        // UINT channel (else FLOAT)
  bool required;  // in every landsim EXR (coverage came later: zero when absent)
};
constexpr Channel kChannels[] = {
    {"R", false, true},         {"G", false, true},           {"B", false, true},
    {"Z", false, true},         {"N.X", false, true},         {"N.Y", false, true},
    {"N.Z", false, true},       {"albedo.R", false, true},    {"albedo.G", false, true},
    {"albedo.B", false, true},  {"object", true, true},       {"species", true, true},
    {"instance", true, true},   {"lod", true, true},          {"target", true, true},
    {"coverage", false, false}, {"P.X", false, false},        {"P.Y", false, false},
    {"P.Z", false, false},      {"Y.variance", false, false}, {"spp", true, false}};

// Sensor bands are channels of their own: "band." and the band's name.
constexpr std::string_view kBandPrefix = "band.";
// Derived planes the film holds as bands, under their own layer names.
constexpr std::string_view kLayerPrefixes[] = {"photons.", "reflectance."};

// The frame buffer for every channel of `film` (const_cast: OpenEXR's Slice wants a
// non-const pointer even for writing).
Imf::FrameBuffer frame_buffer(Film& film) {
  Imf::FrameBuffer fb;
  const int w = film.width();
  add_slice(fb, "R", Imf::FLOAT, film.rgb_data(), 3, 0, w);
  add_slice(fb, "G", Imf::FLOAT, film.rgb_data(), 3, 1, w);
  add_slice(fb, "B", Imf::FLOAT, film.rgb_data(), 3, 2, w);
  add_slice(fb, "Z", Imf::FLOAT, film.depth_data(), 1, 0, w);
  add_slice(fb, "N.X", Imf::FLOAT, film.normal_data(), 3, 0, w);
  add_slice(fb, "N.Y", Imf::FLOAT, film.normal_data(), 3, 1, w);
  add_slice(fb, "N.Z", Imf::FLOAT, film.normal_data(), 3, 2, w);
  add_slice(fb, "albedo.R", Imf::FLOAT, film.albedo_data(), 3, 0, w);
  add_slice(fb, "albedo.G", Imf::FLOAT, film.albedo_data(), 3, 1, w);
  add_slice(fb, "albedo.B", Imf::FLOAT, film.albedo_data(), 3, 2, w);
  add_slice(fb, "object", Imf::UINT, film.object_data(), 1, 0, w);
  add_slice(fb, "species", Imf::UINT, film.species_data(), 1, 0, w);
  add_slice(fb, "instance", Imf::UINT, film.instance_data(), 1, 0, w);
  add_slice(fb, "lod", Imf::UINT, film.level_data(), 1, 0, w);
  add_slice(fb, "target", Imf::UINT, film.target_data(), 1, 0, w);
  add_slice(fb, "coverage", Imf::FLOAT, film.coverage_data(), 1, 0, w);
  add_slice(fb, "P.X", Imf::FLOAT, film.position_data(), 3, 0, w);
  add_slice(fb, "P.Y", Imf::FLOAT, film.position_data(), 3, 1, w);
  add_slice(fb, "P.Z", Imf::FLOAT, film.position_data(), 3, 2, w);
  add_slice(fb, "Y.variance", Imf::FLOAT, film.variance_data(), 1, 0, w);
  add_slice(fb, "spp", Imf::UINT, film.samples_data(), 1, 0, w);
  for (int b = 0; b < film.band_count(); ++b)
    add_slice(fb, band_layer(film.band_name(b)).c_str(), Imf::FLOAT, film.band_data(b), 1, 0, w);
  return fb;
}

Imath::M44f to_m44(const std::array<float, 16>& m) {
  return Imath::M44f(m[0], m[4], m[8], m[12], m[1], m[5], m[9], m[13], m[2], m[6], m[10], m[14],
                     m[3], m[7], m[11], m[15]);
}

}  // namespace

const char* ocio_config_text() { return kOcioConfig; }

std::string band_layer(const std::string& name) {
  return name.find('.') != std::string::npos ? name : std::string(kBandPrefix) + name;
}

void write_exr(const Film& film, const std::filesystem::path& path, const ImageMetadata& metadata,
               const CameraMatrices* camera, bool compressed) {
  AtomicFile out(path);
  Imf::Header header(film.width(), film.height());
  header.compression() = compressed ? Imf::ZIP_COMPRESSION : Imf::NO_COMPRESSION;
  for (const Channel& c : kChannels)
    header.channels().insert(c.name, Imf::Channel(c.id ? Imf::UINT : Imf::FLOAT));
  for (const std::string& name : film.band_names())
    header.channels().insert(band_layer(name), Imf::Channel(Imf::FLOAT));
  if (film.band_count() > 0) header.insert("landsim/band_unit", Imf::StringAttribute(kBandUnit));
  for (const auto& [key, value] : metadata)
    header.insert("landsim/" + key, Imf::StringAttribute(value));
  if (camera != nullptr) {
    // Imath is column-vector-on-the-right transposed: OpenEXR stores row-vector matrices.
    Imf::addWorldToCamera(header, to_m44(camera->world_to_camera));
    if (camera->has_ndc) Imf::addWorldToNDC(header, to_m44(camera->world_to_ndc));
  }
  // Photometric units, stated the standard way (whiteLuminance: the cd/m2 of RGB (1, 1, 1);
  // Rec. 709 primaries and white) and in words.
  Imf::addChromaticities(header, Imf::Chromaticities());
  Imf::addWhiteLuminance(header, 1.0f);
  header.insert("landsim/unit", Imf::StringAttribute(kRadianceUnit));
  // Y: luminance, for users who measure contrast or detectability in cd/m2.
  header.channels().insert("Y", Imf::Channel(Imf::FLOAT));
  std::vector<float> luminance(film.pixel_count());
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      luminance[static_cast<std::size_t>(y) * static_cast<std::size_t>(film.width()) +
                static_cast<std::size_t>(x)] = film.luminance(x, y);
  Film& writable = const_cast<Film&>(film);
  Imf::FrameBuffer fb = frame_buffer(writable);
  add_slice(fb, "Y", Imf::FLOAT, luminance, 1, 0, film.width());
  {
    Imf::OutputFile file(out.temp_path().c_str(), header, exr_threads());
    file.setFrameBuffer(fb);
    file.writePixels(film.height());
  }  // closed before the rename
  out.commit();
}

namespace {

// The "landsim/..." string attributes of a header, without the prefix.
ImageMetadata landsim_metadata(const Imf::Header& header) {
  ImageMetadata metadata;
  for (auto it = header.begin(); it != header.end(); ++it) {
    const std::string name = it.name();
    if (name.rfind("landsim/", 0) != 0) continue;
    if (const auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
      metadata.emplace_back(name.substr(8), s->value());
  }
  return metadata;
}

}  // namespace

Film read_exr(const std::filesystem::path& path, ImageMetadata* metadata) {
  Imf::InputFile in(path.c_str());
  const Imath::Box2i dw = in.header().dataWindow();
  std::vector<std::string> bands;
  for (auto it = in.header().channels().begin(); it != in.header().channels().end(); ++it) {
    const std::string name = it.name();
    if (name.rfind(kBandPrefix, 0) == 0) bands.push_back(name.substr(kBandPrefix.size()));
    for (const std::string_view prefix : kLayerPrefixes)
      if (name.rfind(prefix, 0) == 0) bands.push_back(name);
  }
  Film film(dw.max.x - dw.min.x + 1, dw.max.y - dw.min.y + 1, std::move(bands));
  for (const Channel& c : kChannels) {
    if (c.required && in.header().channels().findChannel(c.name) == nullptr) {
      throw std::runtime_error(path.string() + ": not a landsim image (no channel " + c.name + ")");
    }
  }
  in.setFrameBuffer(frame_buffer(film));
  in.readPixels(dw.min.y, dw.max.y);
  if (metadata != nullptr) *metadata = landsim_metadata(in.header());
  return film;
}

ImageMetadata read_exr_metadata(const std::filesystem::path& path) {
  const Imf::InputFile in(path.c_str());
  return landsim_metadata(in.header());
}

void write_preview_png(const Film& film, const std::filesystem::path& path,
                       std::optional<double> ev100, const std::vector<ImageLabel>& labels) {
  AtomicFile out(path);
  FloatImage image{film.width(), film.height(), 3, film.rgb_data()};
  const auto gain = static_cast<float>(preview_gain(exposure_ev100(film, ev100)));
  for (float& v : image.pixels) v = std::max(0.0f, v * gain);
  std::string error, warning;
  if (!image_io().display_transform(kOcioConfig, image.pixels.data(), image.width, image.height,
                                    error) ||
      !image_io().write_png(out.temp_path().string(), image, false, labels, error, warning)) {
    throw std::runtime_error("writing " + path.string() + " failed: " + error);
  }
  if (!warning.empty()) spdlog::warn("{}: {}", path.string(), warning);
  out.commit();
}

}  // namespace landsim::renderer
