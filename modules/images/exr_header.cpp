#include "modules/images/exr_header.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

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
std::string printable(const std::string& name) {
  std::string out;
  for (const char c : name.substr(0, 40)) out.push_back(c >= 0x20 && c < 0x7f ? c : '?');
  return out + (name.size() > 40 ? "..." : "");
}

}  // namespace

std::string exr_attribute_beyond_file(const std::string& path) {
  std::error_code error;
  const auto file_bytes = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  std::uint32_t magic = 0, version = 0;
  if (error || !little_endian_32(in, magic) || !little_endian_32(in, version)) return "";
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

}  // namespace landsim::images
