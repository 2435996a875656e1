#pragma once
// An OpenEXR header checked before OpenImageIO opens the file (image_fuzz: files of a few
// hundred bytes costing seconds and gigabytes). The image module has OpenImageIO read OpenEXR
// through OpenEXRCore, OpenEXR's strict reader; its C++ reader, the default, allocates from
// what a header claims before it finds the claim false and reads on past a damaged attribute
// into whatever follows. Two checks, in order:
// - the attributes' sizes walked without reading their values (a header is a run of
//   attributes, each a name, a type name, a 32-bit little-endian size and the value, ending in
//   an empty name; a multi-part file has one header per part and an empty one after the
//   last): none may claim more bytes than are left in the file;
// - every part's header read by OpenEXRCore, its allocations bounded by the file: a header it
//   refuses, or reports an error in, is refused, and a part may claim no more values than landsim
//   reads and no more bytes of pixels than its codec decodes from the file (codec_limits.h).
#include <cstddef>
#include <string>

namespace landsim::images {

// While it lives, OpenEXRCore's allocations on this thread are limited to what a header of the
// file at `path` can need (1 MiB and twice the file), in every context, OpenImageIO's too: its
// bounded allocator is made OpenEXRCore's default the first time. OpenImageIO opens files
// through its own reading function, with which OpenEXRCore does not check an attribute's size
// against the file: an "opaque" attribute claiming 1.6 GB in a 392-byte file was allocated
// (in Release address space only, 5-8 s under ASan), though this module's check, reading by
// path, had seen the same header within the file.
class HeaderAllocationLimit {
 public:
  explicit HeaderAllocationLimit(const std::string& path);
  ~HeaderAllocationLimit();
  HeaderAllocationLimit(const HeaderAllocationLimit&) = delete;
  HeaderAllocationLimit& operator=(const HeaderAllocationLimit&) = delete;

 private:
  std::size_t previous_;
};

// Why the OpenEXR file at `path` is refused from its header, or "": an attribute claiming
// more bytes than the file has left, a header OpenEXRCore refuses (its message quoted), or a
// part claiming more than `max_values` values or more bytes than its codec could decode.
std::string exr_header_refusal(const std::string& path, long long max_values);

}  // namespace landsim::images
