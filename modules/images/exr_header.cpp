#include "modules/images/exr_header.h"

#include "modules/images/codec_limits.h"

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <OpenEXR/openexr.h>

namespace landsim::images {
namespace {

constexpr std::uint32_t kMultiPart = 0x1000;  // the version field's multi-part flag
constexpr std::size_t kLongestName = 255;     // OpenEXR's long names

// The null-terminated name or type at the stream's position; false if the file ends first or
// it is longer than any OpenEXR allows.
bool text(std::istream& in, std::string& out) {
  out.clear();
  for (char c = 0; in.get(c);) {
    if (c == '\0') return true;
    if (out.size() == kLongestName) return false;
    out.push_back(c);
  }
  return false;
}

bool little_endian_32(std::istream& in, std::uint32_t& out) {
  unsigned char b[4];
  if (!in.read(reinterpret_cast<char*>(b), 4)) return false;
  out = b[0] | b[1] << 8 | b[2] << 16 | static_cast<std::uint32_t>(b[3]) << 24;
  return true;
}

// A name as a message can show it: a damaged header's bytes are rarely text.
std::string printable(const std::string& name, std::size_t longest = 40) {
  std::string out;
  for (const char c : name.substr(0, longest)) out.push_back(c >= 0x20 && c < 0x7f ? c : '?');
  return out + (name.size() > longest ? "..." : "");
}

// An attribute claiming more bytes than are left in the file, or "": the attributes' sizes
// walked without reading their values (OpenEXR allocates an attribute of a type it does not
// know at its declared size before it finds the file short).
std::string attribute_beyond_file(const std::string& path, std::uintmax_t file_bytes) {
  std::ifstream in(path, std::ios::binary);
  std::uint32_t magic = 0, version = 0;
  if (!little_endian_32(in, magic) || !little_endian_32(in, version)) return "";
  const bool multi_part = (version & kMultiPart) != 0;
  for (std::string name, type;;) {                   // headers
    if (!text(in, name) || name.empty()) return "";  // no header, or the end of the list
    while (!name.empty()) {                          // the header's attributes
      std::uint32_t size = 0;
      if (!text(in, type) || !little_endian_32(in, size)) return "";
      const auto left = file_bytes - static_cast<std::uintmax_t>(in.tellg());
      if (size > left)
        return "the OpenEXR header's attribute \"" + printable(name) + "\" (" + printable(type) +
               ") declares " + std::to_string(size) + " bytes, more than the " +
               std::to_string(left) + " left in the file";
      in.seekg(size, std::ios::cur);
      if (!text(in, name)) return "";
    }
    if (!multi_part) return "";
  }
}

// What a part's header claims of its pixels.
struct PartClaim {
  double width = 0, height = 0;
  long long channels = 0;
  double pixel_bytes = 0;     // the channels' bytes per pixel (half 2, float and uint 4)
  bool uncompressed = false;  // compression "none"
  bool bounded = true;        // a codec of codec_limits.h's bound (all but DWAA and DWAB)
};

// Why a part claiming this is refused, or "": more values than `max_values`, or more bytes of
// pixels than its compression decodes from the whole file (the bounds of codec_limits.h, as
// the image module applies them to OpenImageIO's spec), checked before OpenImageIO opens the
// file (OpenEXR's C++ reader sized its line buffers from them on opening: a 437-byte B44A file
// claiming 2752520 x 8 pixels of 3 channels took over 10 s under ASan).
std::string claim_refusal(const PartClaim& part, std::uintmax_t file_bytes, long long max_values) {
  if (!(part.width > 0 && part.height > 0)) return "";  // OpenEXR says what is wrong
  const std::string pixels = "the OpenEXR header declares " +
                             std::to_string(static_cast<long long>(part.width)) + " x " +
                             std::to_string(static_cast<long long>(part.height)) + " pixels of " +
                             std::to_string(part.channels) + " channels";
  if (part.width * part.height * static_cast<double>(part.channels) >
      static_cast<double>(max_values))
    return pixels + ", more than the " + std::to_string(max_values) + " values landsim reads";
  const double bytes = part.width * part.height * part.pixel_bytes;
  const auto file = static_cast<double>(file_bytes);
  const bool beyond =
      part.uncompressed ? bytes > file
                        : part.bounded && bytes > kBelievedBytes && bytes > kMaxCompression * file;
  if (!beyond) return "";
  return pixels + " (" + std::to_string(static_cast<long long>(bytes)) + " bytes), more than " +
         (part.uncompressed ? "the file holds" : "its compression decodes from the file") + "'s " +
         std::to_string(file_bytes) + " bytes";
}

// The most OpenEXRCore may allocate on this thread now (HeaderAllocationLimit): no value of a
// header needs more than the file holds, so while a header is read its allocator refuses the
// rest (a string attribute claiming a gigabyte fails instead of being zero-filled).
thread_local std::size_t t_allocation_limit = SIZE_MAX;

void* bounded_allocation(std::size_t bytes) {
  return bytes > t_allocation_limit ? nullptr : std::malloc(bytes);
}

// OpenEXRCore's message, kept for the refusal instead of printed on standard error.
void keep_error(exr_const_context_t context, exr_result_t, const char* message) {
  void* kept = nullptr;
  if (exr_get_user_data(context, &kept) == EXR_ERR_SUCCESS && kept != nullptr && message)
    *static_cast<std::string*>(kept) = message;
}

// Part `p` as OpenEXRCore read it; false if it lacks a window or channels (OpenEXR says so).
bool strict_claim(exr_const_context_t context, int p, PartClaim& part) {
  exr_attr_box2i_t window{};
  const exr_attr_chlist_t* channels = nullptr;
  exr_compression_t compression = EXR_COMPRESSION_NONE;
  if (exr_get_data_window(context, p, &window) != EXR_ERR_SUCCESS ||
      exr_get_channels(context, p, &channels) != EXR_ERR_SUCCESS || channels == nullptr ||
      exr_get_compression(context, p, &compression) != EXR_ERR_SUCCESS)
    return false;
  part.width = static_cast<double>(window.max.x) - window.min.x + 1;
  part.height = static_cast<double>(window.max.y) - window.min.y + 1;
  part.channels = channels->num_channels;
  for (int c = 0; c < channels->num_channels; ++c)
    part.pixel_bytes += channels->entries[c].pixel_type == EXR_PIXEL_HALF ? 2 : 4;
  part.uncompressed = compression == EXR_COMPRESSION_NONE;
  part.bounded = compression != EXR_COMPRESSION_DWAA && compression != EXR_COMPRESSION_DWAB;
  return true;
}

// A header OpenEXRCore cannot read, or a part it reads whose claim is refused, or "". Every
// part's header is read by OpenEXRCore, bounded by the file, and nothing else of the file. The
// image module has OpenImageIO read OpenEXR files through OpenEXRCore too, so what is checked
// here is what is read: OpenEXR's C++ reader, OpenImageIO's default, reads on past a damaged
// attribute into whatever follows (a channel list without its closing null gave it another
// data window; a string attribute there claimed 1.7 GB, which it zero-filled: 11 s, 1.8 GB).
std::string strict_refusal(const std::string& path, std::uintmax_t file_bytes,
                           long long max_values) {
  std::string error;
  exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
  init.error_handler_fn = keep_error;
  init.user_data = &error;
  const HeaderAllocationLimit limit(path);
  exr_context_t context = nullptr;
  // OpenEXRCore goes on past some errors it reports (an attribute's size beyond the file) and
  // returns success: a header with an error is damaged all the same.
  if (exr_start_read(&context, path.c_str(), &init) != EXR_ERR_SUCCESS || !error.empty()) {
    exr_finish(&context);
    return "not a valid OpenEXR header (" + (error.empty() ? "unreadable" : printable(error, 200)) +
           ")";
  }
  std::string refusal;
  int parts = 0;
  exr_get_count(context, &parts);
  for (int p = 0; p < parts && refusal.empty(); ++p)
    if (PartClaim part; strict_claim(context, p, part))
      refusal = claim_refusal(part, file_bytes, max_values);
  exr_finish(&context);
  return refusal;
}

}  // namespace

HeaderAllocationLimit::HeaderAllocationLimit(const std::string& path)
    : previous_(t_allocation_limit) {
  static const bool installed = [] {
    exr_set_default_memory_routines(bounded_allocation, std::free);
    return true;
  }();
  (void)installed;
  std::error_code error;
  const auto file_bytes = std::filesystem::file_size(path, error);
  if (!error) t_allocation_limit = static_cast<std::size_t>((1u << 20) + 2 * file_bytes);
}

HeaderAllocationLimit::~HeaderAllocationLimit() { t_allocation_limit = previous_; }

std::string exr_header_refusal(const std::string& path, long long max_values) {
  std::error_code error;
  const auto file_bytes = std::filesystem::file_size(path, error);
  if (error) return "";
  std::string refusal = attribute_beyond_file(path, file_bytes);
  return refusal.empty() ? strict_refusal(path, file_bytes, max_values) : refusal;
}

}  // namespace landsim::images
