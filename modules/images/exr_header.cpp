#include "modules/images/exr_header.h"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

#include <OpenEXR/ImfChannelList.h>
#include <OpenEXR/ImfHeader.h>
#include <OpenEXR/ImfStdIO.h>
#include <OpenEXR/ImfVersion.h>
#include <OpenEXR/ImfXdr.h>

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

// An attribute claiming more bytes than are left in the file, or "": the attributes' sizes
// walked without reading their values (OpenEXR allocates an attribute of a type it does not
// know at its declared size before it finds the file short).
std::string attribute_beyond_file(const std::string& path) {
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

// A part whose data window and channels make more than `max_values` values, or "": every
// part's header read by OpenEXR's own reader (its attribute readers, not the sizes, decide
// where a damaged header's next attribute begins), and nothing more of the file.
std::string values_beyond(const std::string& path, long long max_values) {
  try {
    Imf::StdIFStream in(path.c_str());
    char magic[4];
    in.read(magic, 4);
    int version = 0;
    Imf::Xdr::read<Imf::StreamIO>(in, version);
    if (!Imf::isImfMagic(magic)) return "";
    for (;;) {
      Imf::Header header;
      header.readFrom(in, version);
      const Imath::Box2i window = header.dataWindow();
      const double width = static_cast<double>(window.max.x) - window.min.x + 1;
      const double height = static_cast<double>(window.max.y) - window.min.y + 1;
      long long channels = 0;
      for (auto c = header.channels().begin(); c != header.channels().end(); ++c) ++channels;
      if (width > 0 && height > 0 &&
          width * height * static_cast<double>(channels) > static_cast<double>(max_values))
        return "the OpenEXR header declares " + std::to_string(static_cast<long long>(width)) +
               " x " + std::to_string(static_cast<long long>(height)) + " pixels of " +
               std::to_string(channels) + " channels, more than the " + std::to_string(max_values) +
               " values landsim reads";
      if (!Imf::isMultiPart(version)) return "";
      char next = 0;  // a multi-part file's list of headers ends with an empty one
      const std::uint64_t at = in.tellg();
      in.read(&next, 1);
      if (next == 0) return "";
      in.seekg(at);
    }
  } catch (const std::exception&) {
    return "";  // OpenEXR says what is wrong when the file is opened
  }
}

}  // namespace

std::string exr_header_refusal(const std::string& path, long long max_values) {
  std::string refusal = attribute_beyond_file(path);
  return refusal.empty() ? values_beyond(path, max_values) : refusal;
}

}  // namespace landsim::images
