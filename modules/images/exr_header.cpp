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

// The channels of a "chlist" value: entries of a name and 16 bytes, ended by an empty name.
long long channel_count(const std::string& list) {
  long long count = 0;
  for (std::size_t at = 0; at < list.size() && list[at] != '\0'; ++count) {
    const std::size_t end = list.find('\0', at);
    if (end == std::string::npos) break;
    at = end + 1 + 16;
  }
  return count;
}

// What one header declares of the pixels, as far as it says.
struct Declared {
  double width = 0, height = 0;
  long long channels = 0;
};

// Reads the value of the attribute (name, type, size) at the stream's position into
// `declared` if it is the data window or the channel list, else skips it.
void read_value(std::istream& in, const std::string& name, const std::string& type,
                std::uint32_t size, Declared& declared) {
  if (name == "dataWindow" && type == "box2i" && size == 16) {
    std::uint32_t box[4];
    for (std::uint32_t& v : box) little_endian_32(in, v);
    const auto coordinate = [](std::uint32_t v) {
      return static_cast<double>(static_cast<std::int32_t>(v));
    };
    declared.width = coordinate(box[2]) - coordinate(box[0]) + 1;
    declared.height = coordinate(box[3]) - coordinate(box[1]) + 1;
  } else if (name == "channels" && type == "chlist") {
    std::string list(size, '\0');
    in.read(list.data(), size);
    declared.channels = channel_count(list);
  } else {
    in.seekg(size, std::ios::cur);
  }
}

}  // namespace

std::string exr_header_refusal(const std::string& path, long long max_values) {
  std::error_code error;
  const auto file_bytes = std::filesystem::file_size(path, error);
  std::ifstream in(path, std::ios::binary);
  std::uint32_t magic = 0, version = 0;
  if (error || !little_endian_32(in, magic) || !little_endian_32(in, version)) return "";
  const bool multi_part = (version & kMultiPart) != 0;
  for (std::string name, type;;) {                   // headers
    if (!text(in, name) || name.empty()) return "";  // no header, or the end of the list
    Declared declared;
    while (!name.empty()) {  // the header's attributes
      std::uint32_t size = 0;
      if (!text(in, type) || !little_endian_32(in, size)) return "";
      const auto left = file_bytes - static_cast<std::uintmax_t>(in.tellg());
      if (size > left)
        return "the OpenEXR header's attribute \"" + printable(name) + "\" (" + printable(type) +
               ") declares " + std::to_string(size) + " bytes, more than the " +
               std::to_string(left) + " left in the file";
      read_value(in, name, type, size, declared);
      if (!text(in, name)) return "";
    }
    if (declared.width > 0 && declared.height > 0 &&
        declared.width * declared.height * static_cast<double>(declared.channels) >
            static_cast<double>(max_values))
      return "the OpenEXR header declares " +
             std::to_string(static_cast<long long>(declared.width)) + " x " +
             std::to_string(static_cast<long long>(declared.height)) + " pixels of " +
             std::to_string(declared.channels) + " channels, more than the " +
             std::to_string(max_values) + " values landsim reads";
    if (!multi_part) return "";
  }
}

}  // namespace landsim::images
