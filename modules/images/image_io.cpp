// liblandsim_images.so: the image function table of renderer/output/image_io.h on OpenImageIO and
// OpenColorIO. Loaded by landsim the first time an image file is read or a PNG written
// (core/module_loader.h).
#include "renderer/output/image_io.h"

#include "modules/images/codec_limits.h"
#include "modules/images/exr_header.h"
#include "modules/images/library_noise.h"

#include <OpenColorIO/OpenColorIO.h>
#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <utility>
#include <vector>

namespace OCIO = OCIO_NAMESPACE;

namespace landsim::renderer {
namespace {

constexpr const char* kLabelFont = "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";

// The most values (pixels x channels) an image may hold: 2^28 floats, 1 GiB. The header is
// read first, so a file claiming 100000 x 100000 pixels is refused before anything is
// allocated for it.
constexpr long long kMaxValues = 1LL << 28;
// The most bytes of samples in the file's own types: 1 GiB, as many as the floats (an image
// of 2^28 doubles would have its rows read through 2 GiB buffers).
constexpr double kMaxSampleBytes = 1 << 30;

// OpenImageIO's errors, one per line as each layer adds its own (a truncated PNG: "Read error:
// hit end of file", "PNG read error: IDAT: ...", "PNG library error"), made one line: the
// caller puts the file's name in front of a single message.
std::string one_line(const std::string& errors) {
  std::vector<std::string> lines;
  std::istringstream text(errors);
  for (std::string line; std::getline(text, line);)
    if (!line.empty()) lines.push_back(line);
  // A broken file can fail strip after strip: the first few errors say why, a count the rest.
  constexpr std::size_t kSaid = 3, kCompared = 64;
  std::vector<std::string> kept;
  const std::size_t compared = std::min(lines.size(), kCompared);
  for (std::size_t i = 0; i < compared; ++i) {
    // A line another one repeats within itself says nothing more.
    bool repeated = false;
    for (std::size_t j = 0; j < compared; ++j)
      repeated = repeated ||
                 (j != i && lines[j].size() > lines[i].size() &&
                  lines[j].find(lines[i]) != std::string::npos) ||
                 (j < i && lines[j] == lines[i]);  // said already
    if (!repeated) kept.push_back(lines[i]);
  }
  std::string out;
  for (std::size_t i = 0; i < std::min(kept.size(), kSaid); ++i)
    out += (out.empty() ? "" : "; ") + kept[i];
  const std::size_t more = kept.size() - std::min(kept.size(), kSaid) + (lines.size() - compared);
  if (more > 0) out += "; and " + std::to_string(more) + " more errors";
  return out;
}

// "the header declares W x H pixels of C channels": what a refusal from the header quotes.
std::string declared(const OIIO::ImageSpec& spec) {
  return "the header declares " + std::to_string(spec.width) + " x " + std::to_string(spec.height) +
         " pixels of " + std::to_string(spec.nchannels) +
         (spec.nchannels == 1 ? " channel" : " channels");
}

// The codec's name as OpenImageIO gives it ("zip", "dwaa:45" -> "dwaa").
std::string codec(const OIIO::ImageSpec& spec) {
  const std::string c = spec.get_string_attribute("compression");
  return c.substr(0, c.find(':'));
}

// TIFF compression schemes libtiff can decode (TIFF 6.0 and its registered extensions); any
// other scheme fails at its first strip, after its strip buffer is allocated (a 186-byte TIFF
// of scheme 31233 claiming one 408 MB strip).
bool tiff_scheme_decodable(int scheme) {
  constexpr int kSchemes[] = {1,     2,     3,     4,     5,     6,     7,     8,     32773, 32908,
                              32909, 32946, 34661, 34676, 34677, 34712, 34887, 34925, 50000, 50001};
  return std::find(std::begin(kSchemes), std::end(kSchemes), scheme) != std::end(kSchemes);
}

// The most bytes of pixels one byte of the file's codec decodes to, or 0 where no bound is
// known (the value limit alone holds there). TIFF's codecs by scheme number (OpenImageIO names
// no Zstandard). OpenEXR is not among them: exr_header applies its bound to every part before
// the file is opened, from the header OpenImageIO then reads (both through OpenEXRCore).
//
// WebP's lossless coding has no such bound (a Huffman code of one symbol costs no bits a pixel),
// but OpenImageIO 2.4's reader premultiplies the whole declared canvas by alpha before it asks
// whether the frame decoded: a 21-byte WebP claiming 3085 x 6193 pixels took 8 s to fail (16 s
// under ASan). WebP is held to the short-window ratio by choice: photographs and scans stay far
// within it (a smooth 2048 x 2048 gradient compresses 150 times lossy, 60 lossless); only an
// almost flat image, better given as a colour, goes beyond.
double max_ratio(const std::string& format, int tiff_scheme) {
  if (format == "png" || format == "jpeg" || format == "webp") return images::kMaxCompression;
  if (format != "tiff") return 0;
  switch (tiff_scheme) {
    case 5:      // LZW
    case 7:      // JPEG
    case 8:      // deflate
    case 32773:  // PackBits
    case 32946:  // deflate (the old number)
      return images::kMaxCompression;
    case 34925:  // LZMA
    case 50000:  // Zstandard
      return images::kMaxLongWindowCompression;
    default:
      return 0;
  }
}

// Why the file cannot hold what its header declares, or "": more bytes than an uncompressed
// file has, or (compressed) more bytes of pixels
// than its codec could decode from the whole file (a 179-byte LZW or fax TIFF claiming
// hundreds of megabytes was allocated, then failed to decode). CCITT fax codes one-channel
// bilevel images only (TIFF 6.0, sections 3 and 11): more channels or bits is no image (a
// one-channel 32-bit one made libtiff's decoder ask for gigabytes).
std::string beyond_file(const OIIO::ImageInput& in, const std::string& path) {
  const OIIO::ImageSpec& spec = in.spec();
  const std::string c = codec(spec), format = in.format_name();
  std::error_code size_error;
  const auto file_bytes = std::filesystem::file_size(path, size_error);
  // An uncompressed file holds its pixels: a header claiming more bytes than the file has
  // (a 257-byte TIFF claiming 29294 x 8 pixels of 778 channels, 729 MB) is refused before
  // the pixels are allocated, instead of being read as zeros.
  if (c == "none" && !size_error && spec.image_bytes() > file_bytes)
    return declared(spec) + " uncompressed (" + std::to_string(spec.image_bytes()) +
           " bytes), more than the file's " + std::to_string(file_bytes);
  const int bits = spec.get_int_attribute("oiio:BitsPerSample", 8);
  if (c.rfind("ccitt", 0) == 0 && (spec.nchannels != 1 || bits != 1))
    return declared(spec) + " of " + std::to_string(bits) +
           " bits compressed as CCITT fax, which codes one channel of one bit";
  const int scheme = spec.get_int_attribute("tiff:Compression", 1);
  if (format == "tiff" && !tiff_scheme_decodable(scheme))
    return declared(spec) + " compressed by TIFF scheme " + std::to_string(scheme) +
           ", which libtiff does not decode";
  const double ratio = max_ratio(format, scheme);
  if (size_error || ratio == 0) return "";
  const auto bytes = static_cast<double>(spec.image_bytes());
  if (bytes <= images::kBelievedBytes || bytes <= ratio * static_cast<double>(file_bytes))
    return "";
  if (format == "webp")
    return declared(spec) + " (" + std::to_string(spec.image_bytes()) +
           " bytes), more than landsim reads from a WebP of " + std::to_string(file_bytes) +
           " bytes (" + std::to_string(static_cast<long long>(ratio)) + " bytes of pixels a byte)";
  return declared(spec) + " (" + std::to_string(spec.image_bytes()) + " bytes), more than " +
         (!c.empty()         ? c
          : format == "tiff" ? "TIFF scheme " + std::to_string(scheme)
                             : format) +
         " compression decodes from the file's " + std::to_string(file_bytes) + " bytes";
}

// A tile is decoded whole, padding and all: tiles of up to this many values (1024 x 1024
// pixels of 4 channels; GDAL writes 256 x 256 by default, OpenImageIO 64 x 64), or of up to 4
// times the image's, are believed.
constexpr double kBelievedTileValues = 1 << 22;

// Why the file's tiles claim memory its image does not need, or "" (an 8 x 8 TIFF in tiles of
// 8192 x 8192 pixels: 2.2 GB and 9.5 s before its one tile failed to decode; of 65536 x 65536,
// an allocation that stopped the process).
std::string tiles_beyond_image(const OIIO::ImageSpec& spec) {
  if (spec.tile_width <= 0) return "";
  const double tile = static_cast<double>(spec.tile_width) * std::max(spec.tile_height, 1) *
                      std::max(spec.tile_depth, 1) * spec.nchannels;
  const double image = static_cast<double>(spec.width) * spec.height * spec.nchannels;
  if (tile <= std::max(kBelievedTileValues, 4 * image)) return "";
  return declared(spec) + " in tiles of " + std::to_string(spec.tile_width) + " x " +
         std::to_string(spec.tile_height) + " x " + std::to_string(spec.tile_depth) +
         " pixels, more than 4 times the image";
}

// The formats landsim reads, by OpenImageIO's names: photographs and scans for textures
// (JPEG, PNG, TIFF, WebP), linear and high-range images (OpenEXR, Radiance HDR) and what
// POV-Ray writes for a crosscheck (those and Targa, BMP, PPM). OpenImageIO has readers for
// some thirty formats, and it hands a file to any whose signature matches; a reader outside
// this list never sees the bytes (OpenImageIO 2.4's RLA reader never returned from a 797-byte
// file of one pixel). Targa, the one without a signature, is asked last.
constexpr const char* kFormats[] = {"openexr", "tiff", "png", "jpeg", "webp",
                                    "hdr",     "bmp",  "pnm", "targa"};
constexpr const char* kFormatNames =
    "OpenEXR, TIFF, PNG, JPEG, WebP, Radiance HDR, BMP, PNM/PPM or Targa";

// A reader of the file among kFormats, opened, or null with the reason in `error`.
std::unique_ptr<OIIO::ImageInput> open_known(const std::string& path, std::string& error) {
  // OpenEXR files through OpenEXRCore, the strict reader exr_header checks them with (the C++
  // reader can see another header in a damaged file: modules/images/exr_header.h).
  static const bool core = OIIO::attribute("openexr:core", 1);
  (void)core;
  if (!std::filesystem::is_regular_file(path)) {
    error = "no such file";
    return nullptr;
  }
  for (const char* format : kFormats) {
    auto in = OIIO::ImageInput::create(format);
    if (!in || !in->valid_file(path)) continue;
    // OpenEXR: its header checked, then opened with OpenEXRCore's allocations bounded by the
    // file (the pixels are read unbounded).
    std::optional<images::HeaderAllocationLimit> limit;
    if (in->format_name() == std::string("openexr")) {
      error = images::exr_header_refusal(path, kMaxValues);
      if (!error.empty()) return nullptr;
      limit.emplace(path);
    }
    OIIO::ImageSpec spec;
    const bool opened = in->open(path, spec);
    limit.reset();
    if (opened) return in;
    error = one_line(in->geterror());
    if (error.empty()) error = std::string("cannot open it as ") + in->format_name();
    return nullptr;
  }
  error = std::string("not an image in a format landsim reads (") + kFormatNames + ")";
  return nullptr;
}

// Why the header's size is more than landsim reads, or "": no pixels, more than kMaxValues
// values, or more than kMaxSampleBytes of the file's own samples (counted in floating point: a
// PPM of 2^31 - 1 squared pixels overflowed 64-bit integers).
std::string beyond_limits(const OIIO::ImageSpec& spec) {
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
    return "the header gives no pixels";
  if (static_cast<double>(spec.width) * spec.height * spec.nchannels > kMaxValues)
    return declared(spec) + ", more than the " + std::to_string(kMaxValues) +
           " values landsim reads";
  if (static_cast<double>(spec.image_bytes(true)) > kMaxSampleBytes)
    return declared(spec) + " of " + spec.format.c_str() + " (" +
           std::to_string(spec.image_bytes(true)) + " bytes), more than the " +
           std::to_string(static_cast<long long>(kMaxSampleBytes)) + " bytes landsim reads";
  return "";
}

// Opens the file and checks its header: pixels present, and no more than landsim reads or the
// file can hold.
std::unique_ptr<OIIO::ImageInput> open_checked(const std::string& path, std::string& error) {
  auto in = open_known(path, error);
  if (!in) return nullptr;
  std::string refusal = beyond_limits(in->spec());
  if (refusal.empty()) refusal = tiles_beyond_image(in->spec());
  if (refusal.empty()) refusal = beyond_file(*in, path);
  if (refusal.empty()) return in;
  error = std::move(refusal);
  return nullptr;
}

bool probe_file(const std::string& path, int& width, int& height, int& channels,
                std::string& error) {
  const auto in = open_checked(path, error);
  if (!in) return false;
  width = in->spec().width;
  height = in->spec().height;
  channels = in->spec().nchannels;
  return true;
}

// Rows decoded at a time: about 16 MiB of floats, whole tiles, and whole TIFF strips. A band of
// whole strips is decoded straight into the band, each strip's on a core of its own where
// OpenImageIO can; a band that cuts a strip is read a row at a time through a row that
// OpenImageIO zero-fills first (a header claiming rows of 256 MB touched one before failing).
int band_rows(const OIIO::ImageSpec& spec) {
  const auto row_bytes = static_cast<double>(spec.width) * spec.nchannels * sizeof(float);
  const int unit = spec.tile_width > 0
                       ? std::max(spec.tile_height, 1)
                       : std::clamp(spec.get_int_attribute("tiff:RowsPerStrip", 1), 1, spec.height);
  const int units = std::max(1, static_cast<int>((16.0 * (1 << 20)) / (row_bytes * unit)));
  return unit * units;
}

// A band of scanlines, or a tile, in the file's own sample types. Not zero-filled: a file that
// fails to decode touches only what its decoder wrote (a vector's zeros made every refusal of a
// file claiming long rows touch a band of them).
struct NativeBand {
  std::unique_ptr<char[]> bytes;
  std::size_t size = 0;
  char* hold(std::size_t n) {
    if (n > size) {
      bytes.reset(new char[n]);
      size = n;
    }
    return bytes.get();
  }
};

// `rows` rows of `width` pixels in the file's own sample types (rows `native_row` bytes apart)
// as floats at `out`, whose rows are the image's width apart.
bool to_floats(const OIIO::ImageSpec& spec, const char* native, OIIO::stride_t native_row,
               int width, int rows, float* out) {
  const auto pixel = static_cast<OIIO::stride_t>(spec.pixel_bytes(true));
  const auto out_pixel = static_cast<OIIO::stride_t>(spec.nchannels * sizeof(float));
  const OIIO::stride_t out_row = out_pixel * spec.width;
  if (spec.channelformats.empty())  // one type: every channel at once
    return OIIO::convert_image(spec.nchannels, width, rows, 1, native, spec.format, pixel,
                               native_row, OIIO::AutoStride, out, OIIO::TypeDesc::FLOAT, out_pixel,
                               out_row, OIIO::AutoStride);
  // Channels of their own types (OpenEXR): each channel's column converted on its own.
  for (int c = 0; c < spec.nchannels; ++c)
    if (!OIIO::convert_image(1, width, rows, 1, native + spec.pixel_bytes(0, c, true),
                             spec.channelformat(c), pixel, native_row, OIIO::AutoStride, out + c,
                             OIIO::TypeDesc::FLOAT, out_pixel, out_row, OIIO::AutoStride))
      return false;
  return true;
}

// Rows [y, end) of a scanline file appended to `pixels` as floats. Read in the file's own
// sample types and converted here: OpenImageIO 2.4 converts in chunks of at least 256 rows
// (its "read_chunk") whatever the image's height, and allocates the chunk first (a 185-byte
// TIFF 8 rows high with rows of 51 MB asked for 13 GB). The floats grow only once the rows
// have decoded.
bool read_rows(OIIO::ImageInput& in, int y, int end, NativeBand& band, std::vector<float>& pixels) {
  const OIIO::ImageSpec& spec = in.spec();
  const auto native_row = static_cast<OIIO::stride_t>(spec.scanline_bytes(true));
  char* native = band.hold(static_cast<std::size_t>(native_row) * (end - y));
  if (!in.read_scanlines(0, 0, spec.y + y, spec.y + end, spec.z, 0, spec.nchannels,
                         OIIO::TypeDesc::UNKNOWN, native) ||
      in.has_error())
    return false;
  const std::size_t row = static_cast<std::size_t>(spec.width) * spec.nchannels;
  pixels.resize(row * static_cast<std::size_t>(end));
  return to_floats(spec, native, native_row, spec.width, end - y,
                   pixels.data() + row * static_cast<std::size_t>(y));
}

// Rows [y, end) of a tiled file (whole tiles high; OpenImageIO 2.4's read_scanlines divides by
// zero on tiled files) appended to `pixels` as floats, a tile at a time: each read in the
// file's own types into `band`, the part within the image converted into place. OpenImageIO's own
// conversion zero-fills a row of tiles first (an 8 x 8 TIFF in 4096 x 4096 tiles that fail to
// decode touched 650 MB). The floats grow once the band's first tile has decoded. One slice of a
// volume: its first (no reader landsim meets reports more).
bool read_tile_rows(OIIO::ImageInput& in, int y, int end, NativeBand& band,
                    std::vector<float>& pixels) {
  const OIIO::ImageSpec& spec = in.spec();
  char* tile = band.hold(spec.tile_bytes(true));
  const auto native_row = static_cast<OIIO::stride_t>(spec.pixel_bytes(true) * spec.tile_width);
  const std::size_t row = static_cast<std::size_t>(spec.width) * spec.nchannels;
  for (int ty = y; ty < end; ty += spec.tile_height)
    for (int tx = 0; tx < spec.width; tx += spec.tile_width) {
      if (!in.read_tile(spec.x + tx, spec.y + ty, spec.z, OIIO::TypeDesc::UNKNOWN, tile) ||
          in.has_error())
        return false;
      pixels.resize(row * static_cast<std::size_t>(end));
      const int width = std::min(spec.tile_width, spec.width - tx);
      const int rows = std::min(spec.tile_height, end - ty);
      if (!to_floats(spec, tile, native_row, width, rows,
                     pixels.data() + row * static_cast<std::size_t>(ty) +
                         static_cast<std::size_t>(tx) * spec.nchannels))
        return false;
    }
  return true;
}

// Decodes the image a band of rows at a time into `pixels`, which grows as rows arrive: the
// whole size is reserved once the first band has decoded (address space, no memory touched;
// no copy as the rows arrive), so a header claiming far more than the file holds fails at its
// first band having written that band only (a 20-byte WebP claiming 3085 x 12337 pixels
// zero-filled 456 MB before the decoder gave up). Reserved only then: most broken files fail
// at the first band, and under the sanitizers a reservation costs its shadow memory.
bool decode_bands(OIIO::ImageInput& in, std::vector<float>& pixels) {
  const OIIO::ImageSpec& spec = in.spec();
  const std::size_t row = static_cast<std::size_t>(spec.width) * spec.nchannels;
  pixels.clear();
  NativeBand native;
  const int band = band_rows(spec);
  for (int y = 0; y < spec.height; y += band) {
    const int end = std::min(spec.height, y + band);
    if (y == band) pixels.reserve(row * static_cast<std::size_t>(spec.height));
    const bool read = spec.tile_width > 0 ? read_tile_rows(in, y, end, native, pixels)
                                          : read_rows(in, y, end, native, pixels);
    // A strip or tile that failed to decode is an error even where OpenImageIO goes on with
    // zeros and reports success (a 178-byte TIFF of an unknown codec claiming 8 x 29448
    // pixels of 256 channels read as 240 MB of zeros): the first band that fails ends it.
    if (!read || in.has_error()) return false;
  }
  return true;
}

// Decodes straight into the caller's floats and converts them there: one buffer of the image's
// size at the peak (through an ImageBuf, a copy and a converted copy made three). Read through
// ImageInput, not OpenImageIO's shared image cache, which kept a file's spec by name and time
// stamp and so read a file rewritten within the same second with the old spec (a heap overrun).
bool read_file(const std::string& path, bool to_linear, FloatImage& image, std::string& error) {
  const auto in = open_checked(path, error);
  if (!in) return false;
  OIIO::ImageSpec spec = in->spec();
  // The file's own format: integers are display-referred (sRGB encoded), floats linear.
  const bool encoded =
      spec.format.basetype != OIIO::TypeDesc::FLOAT && spec.format.basetype != OIIO::TypeDesc::HALF;
  if (!decode_bands(*in, image.pixels)) {
    error = one_line(in->geterror());
    if (error.empty()) error = "cannot decode the pixels";
    image = FloatImage{};  // no half-decoded pixels for the caller
    return false;
  }
  if (to_linear && encoded) {
    spec.set_format(OIIO::TypeDesc::FLOAT);
    OIIO::ImageBuf pixels(spec, image.pixels.data());  // wraps the floats, copies nothing
    if (!OIIO::ImageBufAlgo::colorconvert(pixels, pixels, "sRGB", "linear")) {
      error = one_line(pixels.geterror());
      image = FloatImage{};
      return false;
    }
  }
  image.width = spec.width;
  image.height = spec.height;
  image.channels = spec.nchannels;
  image.display_referred = encoded;
  return true;
}

// The table's entries: the file's reading with libpng's own lines held back.
bool probe(const std::string& path, int& width, int& height, int& channels, std::string& error) {
  return images::without_library_noise(
      [&] { return probe_file(path, width, height, channels, error); });
}

bool read(const std::string& path, bool to_linear, FloatImage& image, std::string& error) {
  return images::without_library_noise([&] { return read_file(path, to_linear, image, error); });
}

bool display_transform(const char* config_yaml, float* rgb, int width, int height,
                       std::string& error) {
  try {
    std::istringstream text(config_yaml);
    const OCIO::ConstConfigRcPtr config = OCIO::Config::CreateFromStream(text);
    const OCIO::DisplayViewTransformRcPtr transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc("scene_linear");
    transform->setDisplay("sRGB");
    transform->setView("Standard");
    OCIO::PackedImageDesc image(rgb, width, height, 3);
    config->getProcessor(transform)->getDefaultCPUProcessor()->apply(image);
    return true;
  } catch (const std::exception& e) {
    error = e.what();
    return false;
  }
}

bool write_png(const std::string& path, const FloatImage& image, bool encode_srgb,
               const std::vector<ImageLabel>& labels, std::string& error, std::string& warning) {
  const OIIO::ImageSpec spec(image.width, image.height, image.channels, OIIO::TypeDesc::FLOAT);
  // ImageBuf wraps the caller's pixels without writing to them.
  OIIO::ImageBuf buf(spec, const_cast<float*>(image.pixels.data()));
  OIIO::ImageBuf display = encode_srgb ? OIIO::ImageBufAlgo::colorconvert(buf, "linear", "sRGB")
                                       : OIIO::ImageBufAlgo::copy(buf);
  const float white[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  for (const ImageLabel& label : labels) {
    if (!OIIO::ImageBufAlgo::render_text(display, label.x, label.y, label.text, 18, kLabelFont,
                                         white))
      warning = "no font for the labels (" + display.geterror() + ")";
  }
  if (!display.write(path, OIIO::TypeDesc::UINT8, "png")) {
    error = display.geterror();
    return false;
  }
  return true;
}

const ImageIo kTable{read, probe, display_transform, write_png};

}  // namespace
}  // namespace landsim::renderer

extern "C" __attribute__((visibility("default"))) const landsim::renderer::ImageIo*
landsim_image_io() {
  return &landsim::renderer::kTable;
}
