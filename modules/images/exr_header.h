#pragma once
// An OpenEXR header's attribute sizes against its file, before OpenEXR reads it. OpenEXR 3.1
// allocates an attribute of a type it does not know (an "opaque" attribute) at the size the
// header gives, up to 2 GB, before it finds the file too short: harmless address space in a
// Release build, but seconds of shadow memory under the sanitizers, where image_fuzz found
// hundreds-of-bytes files doing it. The header is a run of attributes (name, type name, a
// 32-bit little-endian size, the value) ending in an empty name (OpenEXR file layout,
// "Header"); a multi-part file has one header per part and an empty header after the last.
#include <string>

namespace landsim::images {

// Why the OpenEXR file at `path` cannot hold an attribute its header declares, or "" (also
// for a header this walk cannot follow: OpenEXR then says what is wrong with it).
std::string exr_attribute_beyond_file(const std::string& path);

}  // namespace landsim::images
