#pragma once
// An OpenEXR header checked before OpenImageIO opens the file, where OpenEXR 3.1 allocates from
// what the header claims before it finds the claim false: harmless address space in a Release
// build, but seconds to a minute of shadow memory under the sanitizers, where image_fuzz found
// files of a few hundred bytes doing it. Two checks:
// - an attribute of a type OpenEXR does not know ("opaque") is allocated at its declared size,
//   up to 2 GB: the attributes' sizes are walked first (a header is a run of attributes, each a
//   name, a type name, a 32-bit little-endian size and the value, ending in an empty name; a
//   multi-part file has one header per part and an empty one after the last), none may claim
//   more bytes than are left in the file;
// - the line buffers are sized from the data window and channels when a part is opened: each
//   part's header is then read by OpenEXR's own reader (its attribute readers, not the sizes,
//   decide where a damaged header's next attribute begins) and its values checked.
#include <string>

namespace landsim::images {

// Why the OpenEXR file at `path` is refused from its header, or "" (also for a header these
// checks cannot follow: OpenEXR says what is wrong with it when the file is opened): an
// attribute claiming more bytes than the file has left, or a part whose data window and
// channels make more than `max_values` values.
std::string exr_header_refusal(const std::string& path, long long max_values);

}  // namespace landsim::images
