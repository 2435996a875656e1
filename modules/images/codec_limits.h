#pragma once
// What a compressed image's header is checked against (the image module and its OpenEXR header
// check share them).

namespace landsim::images {

// The most bytes of pixels (in the file's own sample format) one byte of these codecs can
// decode to, with room to spare: deflate (PNG, TIFF and OpenEXR zip) at most 1032, TIFF's
// LZW about 2560 (a full 12-bit table's longest strings), PackBits 64, baseline or
// progressive JPEG 2048 (every 8 x 8 block's DC coefficient takes a bit, four channels),
// OpenEXR's RLE 64, PIZ and PXR24 and B44 less than deflate. Codecs whose ratio has no such
// bound (OpenEXR's DWA, TIFF's WebP, LERC and JBIG, JPEG 2000, fax) keep only the value limit.
// WebP files are held to this ratio by landsim's choice, not the codec's (image_io.cpp).
constexpr double kMaxCompression = 4096.0;
// The same for the long-window codecs TIFF offers: Zstandard's RLE block is 4 bytes for 128 KiB
// (32768; `zstd -19` of zeros reaches 32462), LZMA's most probable match of 273 bytes costs
// about 0.3 bits (about 7300; `xz` of zeros 6843).
constexpr double kMaxLongWindowCompression = 65536.0;
// Below this many bytes of pixels any header is believed (tiny files, generous ratios).
constexpr double kBelievedBytes = 1 << 20;

}  // namespace landsim::images
