#include "renderer/output/image_output.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfFrameBuffer.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfInputFile.h>
#include <OpenEXR/ImfStringAttribute.h>
#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>
#include <zstd.h>

#include "tests/support/temp_dir.h"

namespace landsim::renderer {
namespace {

Film test_film() {
  Film film(5, 3);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      film.set(x, y, {0.1f * static_cast<float>(x), 0.2f * static_cast<float>(y), 0.5f},
               {10.0f + static_cast<float>(x),
                {0.0f, 0.0f, 1.0f},
                {0.3f, 0.3f, 0.3f},
                1,
                kNoId,
                static_cast<std::uint32_t>(y),
                0});
  return film;
}

int file_count(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(ImageOutput, ExrRoundTripsRadianceDepthAndMetadata) {
  testing::TempDir dir;
  const auto path = dir / "v.exr";
  write_exr(test_film(), path, {{"view", "v"}});
  EXPECT_EQ(file_count(dir.path()), 1);  // no temporary left behind

  Imf::InputFile in(path.c_str());
  const auto& dw = in.header().dataWindow();
  ASSERT_EQ(dw.max.x - dw.min.x + 1, 5);
  ASSERT_EQ(dw.max.y - dw.min.y + 1, 3);
  for (const char* c : {"R", "G", "B", "Z", "N.X", "N.Y", "N.Z"}) {
    EXPECT_NE(in.header().channels().findChannel(c), nullptr) << c;
  }
  const auto* view = in.header().findTypedAttribute<Imf::StringAttribute>("landsim/view");
  ASSERT_NE(view, nullptr);
  EXPECT_EQ(view->value(), "v");

  std::vector<float> r(15), z(15);
  Imf::FrameBuffer fb;
  fb.insert("R", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(r.data()), sizeof(float),
                            5 * sizeof(float)));
  fb.insert("Z", Imf::Slice(Imf::FLOAT, reinterpret_cast<char*>(z.data()), sizeof(float),
                            5 * sizeof(float)));
  in.setFrameBuffer(fb);
  in.readPixels(dw.min.y, dw.max.y);
  EXPECT_FLOAT_EQ(r[2 * 5 + 4], 0.4f);
  EXPECT_FLOAT_EQ(z[1 * 5 + 3], 13.0f);
}

TEST(ImageOutput, PreviewPngIsSrgbEncoded) {
  testing::TempDir dir;
  const auto path = dir / "v.png";
  // EV100 -log2(1.2): the preview's gain 1 / (1.2 x 2^EV100) is 1.
  const double unit_gain = -std::log2(1.2);
  write_preview_png(test_film(), path, unit_gain);
  EXPECT_EQ(file_count(dir.path()), 1);
  auto in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in);
  EXPECT_EQ(in->spec().width, 5);
  EXPECT_EQ(in->spec().height, 3);
  std::vector<unsigned char> px(5 * 3 * 3);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
  // Linear 0.5 is sRGB 188 (not 128: the transfer function is applied).
  EXPECT_NEAR(px[2], 188, 1);
  // One EV less doubles linear 0.4 to 0.8, sRGB 231.
  write_preview_png(test_film(), path, unit_gain - 1.0);
  in = OIIO::ImageInput::open(path.string());
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT8, px.data()));
  EXPECT_NEAR(px[(2 * 5 + 2) * 3 + 1], 231, 1);
}

// The image module's errors reach the user as one line: a truncated PNG's read error comes
// from three layers (the reader, libpng, OpenImageIO), each repeating the last.
TEST(ImageOutput, ImageModuleErrorsAreOneLine) {
  const landsim::testing::TempDir dir;
  const auto path = dir / "whole.png";
  write_preview_png(test_film(), path, 0.0);
  const std::string bytes = landsim::testing::read_file(path);
  const auto truncated = dir.write("truncated.png", bytes.substr(0, bytes.size() / 2));
  FloatImage image;
  std::string error;
  ASSERT_FALSE(image_io().read(truncated.string(), false, image, error));
  EXPECT_FALSE(error.empty());
  EXPECT_EQ(error.find('\n'), std::string::npos) << error;
}

// A lossless WebP of 20 bytes claiming 64 x 64 pixels that do not decode (image_fuzz's input
// of 3085 x 12337 pixels, made small enough to be believed): OpenImageIO reports the decoder's
// failure twice; the user reads it once.
TEST(ImageOutput, AnErrorRepeatedByTheLibrarysLayersIsSaidOnce) {
  const landsim::testing::TempDir dir;
  const std::string bytes{
      "\x2f\x3f\xc0\x0f\x00\x0c\x0c\xf3\xf3\x0c\x0c\x00\x00\x00\x00\x00\xab\x2f\x2f\x2f", 20};
  const auto path = dir.write("claims.webp", bytes);
  FloatImage image;
  std::string error;
  ASSERT_FALSE(image_io().read(path.string(), false, image, error));
  std::vector<std::string> clauses;
  for (std::size_t at = 0, next = 0; at <= error.size(); at = next + 2) {
    next = std::min(error.find("; ", at), error.size());
    clauses.push_back(error.substr(at, next - at));
  }
  ASSERT_FALSE(clauses.front().empty()) << error;
  for (std::size_t i = 0; i < clauses.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_NE(clauses[i], clauses[j]) << error;
}

// Writes 8-bit `pixels` through OpenImageIO with the given compression; false if it cannot.
bool write_8bit(const std::filesystem::path& path, int width, int height, int channels,
                const char* compression, const std::vector<unsigned char>& pixels) {
  OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::UINT8);
  spec.attribute("compression", compression);
  auto out = OIIO::ImageOutput::create(path.string());
  if (!out || !out->open(path.string(), spec) ||
      !out->write_image(OIIO::TypeDesc::UINT8, pixels.data()))
    return false;
  return out->close();
}

// Writes a flat 8-bit image and reads it back whole through the module: the file before it is
// damaged.
bool written_and_read(const std::filesystem::path& path, int width, int height, int channels,
                      const char* compression) {
  const std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * channels, 100);
  FloatImage image;
  std::string error;
  const bool read = write_8bit(path, width, height, channels, compression, pixels) &&
                    image_io().read(path.string(), false, image, error);
  EXPECT_TRUE(read) << path << ": " << error;
  return read && image.pixels.size() == pixels.size();
}

// An uncompressed image claiming more pixels than its file holds is refused from its header,
// before anything is allocated for them (image_fuzz found a 257-byte TIFF read as 729 MB of
// zeros); the whole file reads.
TEST(ImageOutput, AnUncompressedImageLargerThanItsFileIsRefusedFromItsHeader) {
  const landsim::testing::TempDir dir;
  const auto path = dir / "whole.tif";
  ASSERT_TRUE(written_and_read(path, 64, 48, 3, "none"));
  std::string error;
  const std::string bytes = landsim::testing::read_file(path);
  const auto cut = dir.write("cut.tif", bytes.substr(0, bytes.size() / 2));
  int width = 0, height = 0, channels = 0;
  ASSERT_FALSE(image_io().probe(cut.string(), width, height, channels, error));
  EXPECT_NE(error.find("uncompressed (9216 bytes), more than the file's"), std::string::npos)
      << error;
}

// The image module's refusal of `bytes`, written to `dir` as `name` and probed; a message
// saying it was accepted if it was (so that a test looking for its refusal fails saying so).
std::string probe_refusal(const landsim::testing::TempDir& dir, const std::string& name,
                          const std::string& bytes) {
  const auto path = dir.write(name, bytes);
  int width = 0, height = 0, channels = 0;
  std::string error;
  return image_io().probe(path.string(), width, height, channels, error)
             ? "(accepted: " + name + ")"
             : error;
}

// A header of the largest dimensions a reader gives (a PPM of 2^31 - 1 squared pixels) is
// refused by its count of values, counted without overflow (image_fuzz, session 22: the count
// overflowed a 64-bit integer under UBSan).
TEST(ImageOutput, AHeaderOfTheLargestDimensionsIsRefusedByItsValues) {
  const landsim::testing::TempDir dir;
  const std::string error = probe_refusal(
      dir, "huge.ppm", std::string("P6\n2147483647 2147483647\n255\n") + std::string(64, 'x'));
  EXPECT_NE(error.find("the header declares 2147483647 x 2147483647 pixels of 3 channels, more "
                       "than the 268435456 values landsim reads"),
            std::string::npos)
      << error;
}

// A little-endian TIFF of one strip holding `data`: the IFD's entries (tag, value) as LONGs,
// in ascending tag order, then the strip's offset and byte count.
std::string one_strip_tiff(std::vector<std::array<std::uint32_t, 2>> tags,
                           const std::string& data) {
  const auto entries = static_cast<std::uint32_t>(tags.size() + 2);
  const std::uint32_t strip = 8 + 2 + 12 * entries + 4;
  tags.push_back({273, strip});                                    // StripOffsets
  tags.push_back({279, static_cast<std::uint32_t>(data.size())});  // StripByteCounts
  std::string out("II*\0", 4);
  const auto put = [&](std::uint32_t v, int bytes) {
    for (int k = 0; k < bytes; ++k) out.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
  };
  put(8, 4);
  put(entries, 2);
  for (const auto& [tag, value] : tags) {
    put(tag, 2);
    put(4, 2);  // LONG
    put(1, 4);
    put(value, 4);
  }
  put(0, 4);
  return out + data;
}

// A few hundred bytes whose header claims hundreds of megabytes were allocated, then failed
// to decode (image_fuzz, session 20): such headers are refused from the file's size.
TEST(ImageOutput, ACompressedImageBeyondItsCodecsReachIsRefusedFromItsHeader) {
  const landsim::testing::TempDir dir;
  // The probe's refusal of a one-strip TIFF of these tags and strip bytes.
  const auto refusal = [&](const std::vector<std::array<std::uint32_t, 2>>& tags,
                           const std::string& strip) {
    return probe_refusal(dir, "claims.tif", one_strip_tiff(tags, strip));
  };
  // 4000 x 4000 grey in LZW (16 MB) from 100 bytes: LZW decodes at most some 2,560 bytes a byte.
  std::string error =
      refusal({{256, 4000}, {257, 4000}, {258, 8}, {259, 5}, {262, 1}, {277, 1}, {278, 4000}},
              std::string(100, '\x80'));
  EXPECT_NE(error.find("(16000000 bytes), more than lzw compression decodes from the file's"),
            std::string::npos)
      << error;
  // CCITT fax with 314 channels: fax codes one-channel bilevel images only.
  error = refusal({{256, 8}, {257, 65272}, {258, 8}, {259, 3}, {262, 1}, {277, 314}, {278, 8}},
                  std::string(20, '\0'));
  EXPECT_NE(error.find("compressed as CCITT fax, which codes one channel of one bit"),
            std::string::npos)
      << error;
  // One channel of 32 bits (image_fuzz: libtiff's fax decoder asked for gigabytes).
  error = refusal({{256, 8}, {257, 65288}, {258, 32}, {259, 3}, {262, 1}, {277, 1}, {278, 8}},
                  std::string(20, '\0'));
  EXPECT_NE(error.find("of 32 bits compressed as CCITT fax"), std::string::npos) << error;
  // A scheme libtiff lacks, claiming one 408 MB strip (image_fuzz: over 2 GB under ASan).
  error = refusal({{256, 16392}, {257, 8}, {258, 32}, {259, 31233}, {262, 1}, {277, 778}},
                  std::string(20, '\0'));
  EXPECT_NE(error.find("compressed by TIFF scheme 31233, which libtiff does not decode"),
            std::string::npos)
      << error;
  // A lossless WebP of 21 bytes claiming 3085 x 6193 pixels with alpha (image_fuzz, CI of
  // session 28: OpenImageIO premultiplied the whole canvas before the frame failed, 8 s).
  error = probe_refusal(dir, "claims.webp",
                        std::string("\x2f\x0c\x0c\x0c\x16\x0c\x0c\xf3\x0c\x0c\x00\xf3\x00\x00"
                                    "\x21\x00\xab\x2f\xa2\x2f\x2f",
                                    21));
  EXPECT_NE(error.find("the header declares 3085 x 6193 pixels of 4 channels (76421620 bytes), "
                       "more than landsim reads from a WebP of 21 bytes"),
            std::string::npos)
      << error;
  // The same claim in Zstandard with a strip of no bytes (image_fuzz: OpenImageIO asked for
  // 13 GB, 1.8 GB touched under ASan): Zstandard decodes at most some 32,768 bytes a byte.
  error = refusal({{256, 16392}, {257, 8}, {258, 32}, {259, 50000}, {262, 1}, {277, 778}}, "");
  EXPECT_NE(error.find("more than TIFF scheme 50000 compression decodes from the file's"),
            std::string::npos)
      << error;
}

// `tiff` (little-endian) with the value of IFD 0's entry `tag` (SHORT or LONG) made `value`
// (a LONG if a SHORT cannot hold it).
std::string with_tag(std::string tiff, std::uint16_t tag, std::uint32_t value) {
  const auto at = [&](std::size_t i, int bytes) {
    std::uint32_t v = 0;
    for (int k = 0; k < bytes; ++k)
      v |= static_cast<std::uint32_t>(static_cast<unsigned char>(tiff[i + k])) << (8 * k);
    return v;
  };
  const std::uint32_t ifd = at(4, 4);
  for (std::uint32_t e = 0; e < at(ifd, 2); ++e) {
    const std::size_t entry = ifd + 2 + 12 * e;
    if (at(entry, 2) != tag) continue;
    if (value > 0xffff) tiff[entry + 2] = 4;  // LONG: a SHORT cannot hold it
    const int bytes = at(entry + 2, 2) == 3 ? 2 : 4;
    for (int k = 0; k < bytes; ++k)
      tiff[entry + 8 + k] = static_cast<char>((value >> (8 * k)) & 0xff);
  }
  return tiff;
}

// A tile is decoded whole, padding and all: tiles far larger than their image are refused from
// the header (image_fuzz, session 22: an 8 x 8 TIFF in tiles of 8192 x 8192 pixels took
// 2.2 GB and 9.5 s to fail; of 65536 x 65536, an allocation stopped the process), while a small
// image in a writer's usual tiles (GDAL's 256 x 256) reads.
TEST(ImageOutput, TilesFarLargerThanTheirImageAreRefusedFromTheHeader) {
  const landsim::testing::TempDir dir;
  const auto path = dir / "small.tif";
  OIIO::ImageSpec spec(8, 8, 4, OIIO::TypeDesc::FLOAT);
  spec.tile_width = spec.tile_height = 256;
  spec.attribute("compression", "zip");
  const std::vector<float> pixels(8 * 8 * 4, 0.25f);
  auto out = OIIO::ImageOutput::create(path.string());
  ASSERT_TRUE(out && out->open(path.string(), spec));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  out->close();
  FloatImage image;
  std::string error;
  ASSERT_TRUE(image_io().read(path.string(), false, image, error)) << error;
  EXPECT_TRUE(image.pixels == pixels);
  for (const std::uint32_t tile : {8192u, 65536u}) {
    error =
        probe_refusal(dir, "claimed.tif",
                      with_tag(with_tag(landsim::testing::read_file(path), 322, tile), 323, tile));
    EXPECT_NE(error.find("the header declares 8 x 8 pixels of 4 channels in tiles of " +
                         std::to_string(tile) + " x " + std::to_string(tile) +
                         " x 1 pixels, more than 4 times the image"),
              std::string::npos)
        << error;
  }
}

// OpenImageIO goes on past a strip it cannot decode, filling zeros, and reports success with
// the errors on the side: such a file was read as zeros (image_fuzz: 178 bytes claiming 240 MB
// of them). Its first failing band now ends the read, the first errors said and the rest
// counted.
TEST(ImageOutput, AnImageWhoseStripsFailToDecodeIsRefused) {
  const landsim::testing::TempDir dir;
  for (const std::uint32_t codec : {5u, 8u}) {  // LZW and deflate short of data
    const auto path =
        dir.write("strips.tif",
                  one_strip_tiff(
                      {{256, 8}, {257, 4096}, {258, 8}, {259, codec}, {262, 1}, {277, 1}, {278, 8}},
                      std::string(64, '\x80')));
    FloatImage image;
    std::string error;
    ASSERT_FALSE(image_io().read(path.string(), false, image, error)) << codec;
    EXPECT_TRUE(image.pixels.empty());
    EXPECT_NE(error.find("Strip failed reading line"), std::string::npos) << error;
    EXPECT_NE(error.find(" more errors"), std::string::npos) << error;  // 511 strips fail
    EXPECT_LT(error.size(), 600u) << error;
  }
}

// OpenImageIO 2.4 converts scanlines in chunks of at least 256 rows whatever the image's
// height, allocating the chunk first: a header of 8 rows of 128 MB each (a codec without a
// ratio bound, a strip of no bytes) asked for 32 GB and stopped the process with
// std::bad_alloc. The module reads rows in the file's own types and converts them itself; the
// strip's own error is what the reader says. The same rows in doubles, 2 GiB of samples, are
// refused from the header (the floats' limit, 1 GiB, holds for the file's own samples too).
TEST(ImageOutput, AnImageOfLongRowsFailingToDecodeIsRefusedWithTheDecodersError) {
  const landsim::testing::TempDir dir;
  // 8 rows of 2^22 pixels of 8 IEEE floats of `bits` bits, LERC, a strip of no bytes.
  const auto long_rows = [](std::uint32_t bits) {
    return one_strip_tiff({{256, 1u << 22},
                           {257, 8},
                           {258, bits},
                           {259, 34887},
                           {262, 1},
                           {277, 8},
                           {278, 8},
                           {339, 3}},
                          "");
  };
  const auto path = dir.write("long_rows.tif", long_rows(32));
  FloatImage image;
  std::string error;
  ASSERT_FALSE(image_io().read(path.string(), false, image, error));
  EXPECT_TRUE(image.pixels.empty());
  EXPECT_NE(error.find("Invalid strip byte count 0, strip 0"), std::string::npos) << error;
  error = probe_refusal(dir, "long_doubles.tif", long_rows(64));
  EXPECT_NE(
      error.find("of double (2147483648 bytes), more than the 1073741824 bytes landsim reads"),
      std::string::npos)
      << error;
}

// A JPEG cut short read with its missing rows grey, libjpeg's "premature end" an error on the
// side; it is refused like any file that fails to decode.
TEST(ImageOutput, ATruncatedJpegIsRefused) {
  const landsim::testing::TempDir dir;
  const auto path = dir / "whole.jpg";
  std::vector<unsigned char> pixels(64 * 64 * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i)
    pixels[i] = static_cast<unsigned char>((i * 2654435761u) >> 24);  // noise: no tiny file
  ASSERT_TRUE(write_8bit(path, 64, 64, 3, "jpeg", pixels));
  FloatImage image;
  std::string error;
  ASSERT_TRUE(image_io().read(path.string(), false, image, error)) << error;
  const std::string bytes = landsim::testing::read_file(path);
  const auto cut = dir.write("cut.jpg", bytes.substr(0, bytes.size() * 2 / 3));
  ASSERT_FALSE(image_io().read(cut.string(), false, image, error));
  EXPECT_NE(error.find("Premature end of JPEG file"), std::string::npos) << error;
}

// Writes `pixels` (square, `side` pixels, `channels`) with `codec`, then expects them read
// whole from a file at least `ratio` times smaller.
void expect_compressed_and_read(const std::filesystem::path& path, int side, int channels,
                                const char* codec, const std::vector<unsigned char>& pixels,
                                std::size_t ratio) {
  ASSERT_TRUE(write_8bit(path, side, side, channels, codec, pixels)) << path;
  FloatImage image;
  std::string error;
  ASSERT_TRUE(image_io().read(path.string(), false, image, error)) << path << ": " << error;
  EXPECT_EQ(image.pixels.size(), pixels.size()) << path;
  EXPECT_GT(pixels.size() / std::filesystem::file_size(path), ratio) << path;
}

// The bound must not refuse what the codec really does: 4096 x 4096 of one value, the most
// compressible image there is, in LZW TIFF and PNG.
TEST(ImageOutput, HighlyCompressedImagesWithinTheirCodecsReachAreRead) {
  const landsim::testing::TempDir dir;
  const std::vector<unsigned char> pixels(4096 * 4096, 7);
  expect_compressed_and_read(dir / "flat.tif", 4096, 1, "lzw", pixels, 100);
  expect_compressed_and_read(dir / "flat.png", 4096, 1, "zip", pixels, 100);
  // A smooth gradient, the most compressible thing a photograph holds, as lossy and lossless
  // WebP (some 150 and 60 bytes a byte): within the ratio landsim holds WebP to.
  std::vector<unsigned char> gradient(2048 * 2048 * 3);
  for (std::size_t i = 0; i < gradient.size(); ++i) {
    const std::size_t x = i / 3 % 2048, y = i / 3 / 2048;
    gradient[i] = static_cast<unsigned char>((i % 3 == 0 ? x : i % 3 == 1 ? y : (x + y) / 2) / 8);
  }
  expect_compressed_and_read(dir / "lossy.webp", 2048, 3, "webp", gradient, 20);
  expect_compressed_and_read(dir / "lossless.webp", 2048, 3, "lossless", gradient, 20);
  // 16 MiB of zeros in Zstandard's densest form (some 30,000 bytes a byte): the long-window
  // codecs have a bound of their own, above what they reach.
  const std::string zeros(std::size_t{1} << 24, '\0');
  std::string packed(ZSTD_compressBound(zeros.size()), '\0');
  packed.resize(ZSTD_compress(packed.data(), packed.size(), zeros.data(), zeros.size(), 19));
  ASSERT_GT(zeros.size() / packed.size(), 4096u * 4);  // beyond the short-window codecs' bound
  const auto zstd_tiff = dir.write(
      "zeros.tif",
      one_strip_tiff(
          {{256, 4096}, {257, 4096}, {258, 8}, {259, 50000}, {262, 1}, {277, 1}, {278, 4096}},
          packed));
  FloatImage zeros_read;
  std::string zstd_error;
  ASSERT_TRUE(image_io().read(zstd_tiff.string(), false, zeros_read, zstd_error)) << zstd_error;
  ASSERT_EQ(zeros_read.pixels.size(), zeros.size());
  EXPECT_TRUE(std::all_of(zeros_read.pixels.begin(), zeros_read.pixels.end(),
                          [](float v) { return v == 0.0f; }));
  // A blank fax page (CCITT group 4: one bit a row, whatever its width) reads too: the fax
  // rule refuses only what fax cannot code.
  const auto fax = dir.write(
      "blank_g4.tif",
      one_strip_tiff({{256, 1728}, {257, 64}, {258, 1}, {259, 4}, {262, 0}, {277, 1}, {278, 64}},
                     std::string(8, '\xff') + std::string("\x00\x10\x01", 3)));
  FloatImage page;
  std::string error;
  ASSERT_TRUE(image_io().read(fax.string(), false, page, error)) << error;
  ASSERT_EQ(page.pixels.size(), 1728u * 64u);
  EXPECT_TRUE(std::all_of(page.pixels.begin(), page.pixels.end(),
                          [&](float v) { return v == page.pixels.front(); }));
}

// The module decodes a band of rows at a time, scanlines and tiles in the file's own sample
// types and converted by the module; every pixel must still be where OpenImageIO's own
// whole-image read puts it, with the same value: scanline and tiled files (tiles 48 pixels
// square, cut by the image's edges: bands of whole tiles), TIFF strips and tiles of 16 bits,
// 8-bit PNG, OpenEXR channels of two types, a data window that does not start at 0, several
// bands of 16 MiB each.
TEST(ImageOutput, BandedDecodingReadsWhatTheFileHolds) {
  const landsim::testing::TempDir dir;
  const int width = 1500, height = 1100;  // 26 MB of floats in four channels: two bands
  struct Case {
    const char* name;
    OIIO::TypeDesc type;
    int channels;     // PNG's three: OpenImageIO multiplies PNG's colours by their alpha
    float tolerance;  // of the file's sample type against the floats written
  };
  const OIIO::TypeDesc half = OIIO::TypeDesc::HALF;
  for (const Case& c :
       {Case{"lines.exr", OIIO::TypeDesc::FLOAT, 4, 0.0f},
        Case{"tiles.exr", OIIO::TypeDesc::FLOAT, 4, 0.0f},
        Case{"tiles.tif", OIIO::TypeDesc::FLOAT, 4, 0.0f},
        Case{"strips16.tif", OIIO::TypeDesc::UINT16, 4, 0.5f / 65535},
        Case{"lines8.png", OIIO::TypeDesc::UINT8, 3, 0.5f / 255},
        Case{"tiles16.tif", OIIO::TypeDesc::UINT16, 4, 0.5f / 65535},
        Case{"mixed.exr", half, 4, 1.0f / 4096}, Case{"tiles_mixed.exr", half, 4, 1.0f / 4096}}) {
    const std::string name = c.name;
    std::vector<float> pixels(static_cast<std::size_t>(width) * height * c.channels);
    for (std::size_t i = 0; i < pixels.size(); ++i)
      pixels[i] = static_cast<float>((i * 2654435761u) % 1000) / 1000.0f;
    const auto path = dir / name;
    OIIO::ImageSpec spec(width, height, c.channels, c.type);
    if (!name.ends_with(".png")) spec.y = -37;  // the data window starts above the origin
    if (name.starts_with("tiles")) spec.tile_width = spec.tile_height = 48;
    if (name.starts_with("strips")) spec.attribute("compression", "zip");
    const bool mixed = name.find("mixed") != std::string::npos;
    if (mixed) spec.channelformats = {half, half, half, OIIO::TypeDesc::FLOAT};
    auto out = OIIO::ImageOutput::create(path.string());
    ASSERT_TRUE(out && out->open(path.string(), spec)) << name;
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) << name;
    out->close();
    auto in = OIIO::ImageInput::open(path.string());
    ASSERT_TRUE(in) << name;
    if (name.starts_with("strips")) {  // bands of whole strips
      EXPECT_EQ(in->spec().get_int_attribute("tiff:RowsPerStrip"), 32) << name;
    }
    if (mixed) {
      EXPECT_EQ(in->spec().channelformats.size(), 4u) << name;
    }
    std::vector<float> whole(pixels.size());
    ASSERT_TRUE(in->read_image(0, 0, 0, c.channels, OIIO::TypeDesc::FLOAT, whole.data())) << name;
    FloatImage image;
    std::string error;
    ASSERT_TRUE(image_io().read(path.string(), false, image, error)) << name << ": " << error;
    ASSERT_EQ(image.width, width);
    ASSERT_EQ(image.height, height);
    EXPECT_TRUE(image.pixels == whole) << name;
    float off = 0.0f;  // the file held what was written, to its sample type's precision
    for (std::size_t i = 0; i < pixels.size(); ++i)
      off = std::max(off, std::abs(whole[i] - pixels[i]));
    EXPECT_LE(off, c.tolerance * 1.001f) << name;
    EXPECT_GE(off, c.tolerance / 4) << name;  // and that precision was the file's own
  }
}

// The formats landsim reads are found by their contents whatever the file's name (a texture
// saved as "bark.img"), and read whole; a format outside them is refused by name before any of
// its reader runs (OpenImageIO 2.4's RLA reader hung on a 797-byte file of one pixel).
TEST(ImageOutput, TheFormatsLandsimReadsAreFoundByContentAndNoOthersAreRead) {
  const landsim::testing::TempDir dir;
  std::vector<unsigned char> pixels(6 * 4 * 3);
  for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = static_cast<unsigned char>(i * 10);
  for (const char* ext : {"exr", "tif", "png", "jpg", "webp", "hdr", "bmp", "ppm", "tga"}) {
    const auto written = dir / (std::string("image.") + ext);
    ASSERT_TRUE(write_8bit(written, 6, 4, 3, "", pixels)) << ext;
    const auto renamed = dir.write(std::string(ext) + ".img", landsim::testing::read_file(written));
    FloatImage image;
    std::string error;
    ASSERT_TRUE(image_io().read(renamed.string(), false, image, error)) << ext << ": " << error;
    EXPECT_EQ(image.width, 6) << ext;
    EXPECT_EQ(image.height, 4) << ext;
    EXPECT_EQ(image.channels, 3) << ext;
    // The lossless 8-bit formats give back every value.
    if (std::string(ext) == "png" || std::string(ext) == "tif" || std::string(ext) == "bmp" ||
        std::string(ext) == "ppm" || std::string(ext) == "tga") {
      for (std::size_t i = 0; i < pixels.size(); ++i)
        ASSERT_NEAR(image.pixels[i], pixels[i] / 255.0f, 1e-6f) << ext << " value " << i;
    }
  }
  for (const char* ext : {"rla", "sgi", "fits", "dpx"}) {
    const auto path = dir / (std::string("other.") + ext);
    ASSERT_TRUE(write_8bit(path, 6, 4, 3, "", pixels)) << ext;
    FloatImage image;
    std::string error;
    int width = 0, height = 0, channels = 0;
    EXPECT_FALSE(image_io().probe(path.string(), width, height, channels, error)) << ext;
    EXPECT_NE(error.find("not an image in a format landsim reads (OpenEXR, TIFF"),
              std::string::npos)
        << ext << ": " << error;
    EXPECT_FALSE(image_io().read(path.string(), false, image, error)) << ext;
    EXPECT_TRUE(image.pixels.empty()) << ext;
  }
}

// An OpenEXR attribute claiming more bytes than the file holds, or a data window of more values
// than landsim reads, is refused before OpenEXR allocates for it (image_fuzz: files of a few
// hundred bytes took seconds to a minute under the sanitizers); an untouched file, one part or
// several, still reads.
TEST(ImageOutput, AnExrHeaderClaimingTooMuchIsRefusedBeforeOpenExrReadsIt) {
  const landsim::testing::TempDir dir;
  const auto path = dir / "whole.exr";
  ASSERT_TRUE(written_and_read(path, 16, 8, 3, "zip"));
  FloatImage image;
  std::string error;
  // Two parts: the walk follows every header to the empty one after the last.
  const auto parts = dir / "parts.exr";
  {
    OIIO::ImageSpec specs[2] = {OIIO::ImageSpec(16, 8, 3, OIIO::TypeDesc::HALF),
                                OIIO::ImageSpec(16, 8, 1, OIIO::TypeDesc::HALF)};
    specs[0].attribute("oiio:subimagename", "first");  // OpenEXR's parts need names
    specs[1].attribute("oiio:subimagename", "second");
    auto out = OIIO::ImageOutput::create(parts.string());
    ASSERT_TRUE(out && out->open(parts.string(), 2, specs));
    const std::vector<float> first(16 * 8 * 3, 0.5f), second(16 * 8, 0.25f);
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, first.data()));
    ASSERT_TRUE(out->open(parts.string(), specs[1], OIIO::ImageOutput::AppendSubimage));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, second.data()));
    ASSERT_TRUE(out->close());
  }
  ASSERT_TRUE(image_io().read(parts.string(), false, image, error)) << error;
  EXPECT_EQ(image.width, 16);
  // The "channels" attribute's size (after its name and type, "chlist") made 2^31 - 1.
  std::string bytes = landsim::testing::read_file(path);
  const std::size_t size_at = bytes.find(std::string("channels\0chlist\0", 16)) + 16;
  ASSERT_NE(size_at, std::string::npos + 16);
  bytes.replace(size_at, 4, std::string("\xff\xff\xff\x7f", 4));
  error = probe_refusal(dir, "claims.exr", bytes);
  EXPECT_NE(error.find("attribute \"channels\" (chlist) declares 2147483647 bytes, more than the "),
            std::string::npos)
      << error;
  // The data window made 16777224 pixels wide: 402 M values, refused before OpenEXR sizes its
  // line buffers from it (image_fuzz: 55 s under ASan).
  bytes = landsim::testing::read_file(path);
  const std::size_t box_at = bytes.find(std::string("dataWindow\0box2i\0", 17)) + 17 + 4;
  ASSERT_NE(box_at, std::string::npos + 21);
  bytes.replace(box_at + 8, 4, std::string("\x07\x00\x00\x01", 4));  // xMax = 2^24 + 7
  error = probe_refusal(dir, "wide.exr", bytes);
  EXPECT_NE(error.find("the OpenEXR header declares 16777224 x 8 pixels of 3 channels, more than "
                       "the 268435456 values landsim reads"),
            std::string::npos)
      << error;
  // 1048584 pixels wide, within the value limit: 50 MB of half pixels from some 500 bytes of
  // ZIP, which decodes at most some 1032 bytes a byte.
  bytes.replace(box_at + 8, 4, std::string("\x07\x00\x10\x00", 4));  // xMax = 2^20 + 7
  error = probe_refusal(dir, "zip.exr", bytes);
  EXPECT_NE(error.find("the OpenEXR header declares 1048584 x 8 pixels of 3 channels (50332032 "
                       "bytes), more than its compression decodes from the file's"),
            std::string::npos)
      << error;
}

// Damaged OpenEXR files image_fuzz found, on which OpenEXR's C++ reader (OpenImageIO's default)
// read on past a damaged attribute: it zero-filled strings claiming 1.7 GB (11 s, 1.8 GB in
// Release) or sized line buffers from a window only it saw (the strict reader keeps the first
// of two "dataWindow" attributes, 64 x 64, the C++ reader the last, 16777224 x 8). Read now as
// OpenEXRCore reads them, and refused, with what it says (an error it reports refuses the
// header even where it goes on).
TEST(ImageOutput, DamagedExrFilesAreReadAsTheStrictReaderSeesThemAndRefused) {
  const landsim::testing::TempDir dir;
  struct Case {
    const char* input;
    const char* said;
  };
  for (const Case& c :
       {Case{"oom-exr-string-attribute-after-damaged-chlist",
             "not a valid OpenEXR header ('channels' attribute not found)"},
        Case{"timeout-exr-chlist-unterminated", "Some scanline chunks were missing or corrupted"},
        Case{"oom-exr-cpp-reader-string-1.7gb", "Some scanline chunks were missing or corrupted"},
        Case{"timeout-exr-cpp-reader-string", "Some scanline chunks were missing or corrupted"},
        // Within the value limit, claiming (to the C++ reader) far more than their
        // codecs decode from the file.
        Case{"timeout-exr-zip-16777217x1-in-496-bytes",
             "Some scanline chunks were missing or corrupted"},
        Case{"timeout-exr-b44a-2752520x8-in-437-bytes",
             "not a valid OpenEXR header (Invalid empty string encountered parsing attribute type"},
        // OpenEXRCore reported an error in the header and returned success; through
        // OpenImageIO's reading function (no size check against the file) it then allocated
        // an "opaque" attribute of 1.6 GB (image_fuzz, session 22: 5-8 s under ASan).
        Case{"slow-exr-opaque-1.6gb-beyond-file-through-oiio",
             "not a valid OpenEXR header (Invalid empty string encountered parsing attribute type"},
        Case{"slow-exr-core-error-then-success",
             "not a valid OpenEXR header (Invalid empty string encountered parsing attribute "
             "type"}}) {
    // The fuzz input's first byte is the target's choice of name; the file is the rest.
    const std::string bytes = landsim::testing::read_file(
        landsim::testing::source_file(std::string("fuzz/regressions/image_fuzz/") + c.input));
    const auto path = dir.write(std::string(c.input) + ".exr", bytes.substr(1));
    FloatImage image;
    std::string error;
    ASSERT_FALSE(image_io().read(path.string(), false, image, error)) << c.input;
    EXPECT_NE(error.find(c.said), std::string::npos) << c.input << ": " << error;
  }
}

}  // namespace
}  // namespace landsim::renderer
