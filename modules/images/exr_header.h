#pragma once
// An OpenEXR header checked before OpenEXR reads it: its attribute sizes against the file, and
// the values its parts declare. OpenEXR 3.1
// allocates an attribute of a type it does not know (an "opaque" attribute) at the size the
// header gives, up to 2 GB, before it finds the file too short: harmless address space in a
// Release build, but seconds of shadow memory under the sanitizers, where image_fuzz found
// hundreds-of-bytes files doing it. The header is a run of attributes (name, type name, a
// 32-bit little-endian size, the value) ending in an empty name (OpenEXR file layout,
// "Header"); a multi-part file has one header per part and an empty header after the last.
#include <string>

namespace landsim::images {

// Why the OpenEXR file at `path` is refused from its header, or "" (also for a header this walk
// cannot follow: OpenEXR then says what is wrong with it): an attribute claiming more bytes
// than the file has left, or a part whose data window and channels make more than
// `max_values` values (OpenEXR 3.1 sizes its line buffers from them when the file is opened,
// before landsim could check OpenImageIO's spec: 55 s under the sanitizers for a 768-byte
// file claiming 16777224 x 8 pixels of 3 channels).
std::string exr_header_refusal(const std::string& path, long long max_values);

}  // namespace landsim::images
