#include "scenes/builder/detail/mesh_file_check.h"

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "core/input_error.h"

namespace landsim::scenes::detail {
namespace {

namespace fs = std::filesystem;

std::string lower_extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

std::uint32_t little_endian_u32(const unsigned char* b) {
  return static_cast<std::uint32_t>(b[0]) | static_cast<std::uint32_t>(b[1]) << 8 |
         static_cast<std::uint32_t>(b[2]) << 16 | static_cast<std::uint32_t>(b[3]) << 24;
}

[[noreturn]] void refuse(const std::string& where, const std::string& path,
                         const std::string& what) {
  throw InputError(fmt::format("{}: {}: {}", where, path, what));
}

// A glTF's buffers (and images) name files by uri: relative, inside the model's folder, and
// holding at least the bytes the buffer declares. data: uris are embedded; the GLB's own
// binary chunk is buffer 0 without a uri.
void check_gltf_json(const nlohmann::json& gltf, const fs::path& path, const std::string& where) {
  std::error_code resolved;
  const fs::path folder = fs::weakly_canonical(path, resolved).parent_path();
  if (resolved) refuse(where, path.string(), "cannot resolve its folder: " + resolved.message());
  const auto check_uri = [&](const std::string& kind, std::size_t i, const nlohmann::json& item,
                             std::uintmax_t* declared) {
    if (!item.is_object() || !item.contains("uri") || !item["uri"].is_string()) return;
    const std::string uri = item["uri"].get<std::string>();
    if (uri.rfind("data:", 0) == 0) return;
    const fs::path target = fs::weakly_canonical(folder / uri, resolved);
    if (resolved)  // a uri too long for a file name, or one the system cannot follow
      refuse(where, path.string(),
             fmt::format("{}[{}] uri \"{}\" is not a file beside the model ({})", kind, i,
                         uri.substr(0, 80) + (uri.size() > 80 ? "..." : ""), resolved.message()));
    const auto [end, unused] = std::mismatch(folder.begin(), folder.end(), target.begin());
    if (fs::path(uri).is_absolute() || uri.find("://") != std::string::npos || end != folder.end())
      refuse(where, path.string(),
             fmt::format("{}[{}] uri \"{}\" points outside the model's folder (expected a file "
                         "beside the model or below it)",
                         kind, i, uri));
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(target, ec);
    if (ec)
      refuse(where, path.string(),
             fmt::format("{}[{}] uri \"{}\": no such file beside the model", kind, i, uri));
    if (declared != nullptr && *declared > size)
      refuse(where, path.string(),
             fmt::format("{}[{}] (uri \"{}\") declares byteLength {} but the file holds {} bytes",
                         kind, i, uri, *declared, size));
  };
  if (gltf.contains("buffers") && gltf["buffers"].is_array()) {
    const auto& buffers = gltf["buffers"];
    for (std::size_t i = 0; i < buffers.size(); ++i) {
      std::uintmax_t length = 0;
      const bool has_length = buffers[i].is_object() && buffers[i].contains("byteLength") &&
                              buffers[i]["byteLength"].is_number_unsigned();
      if (has_length) length = buffers[i]["byteLength"].get<std::uintmax_t>();
      check_uri("buffers", i, buffers[i], has_length ? &length : nullptr);
    }
  }
  if (gltf.contains("images") && gltf["images"].is_array())
    for (std::size_t i = 0; i < gltf["images"].size(); ++i)
      check_uri("images", i, gltf["images"][i], nullptr);
}

// GLB: a 12-byte header (magic, version, total length), then chunks of (length, type, data).
void check_glb(const fs::path& path, std::uintmax_t size, const std::string& where) {
  std::ifstream in(path, std::ios::binary);
  std::array<unsigned char, 12> header{};
  if (!in.read(reinterpret_cast<char*>(header.data()), header.size()) ||
      std::memcmp(header.data(), "glTF", 4) != 0)
    refuse(where, path.string(),
           "a .glb file begins with the magic \"glTF\" and this one does not");
  const std::uint32_t length = little_endian_u32(&header[8]);
  if (length > size)
    refuse(where, path.string(),
           fmt::format("the GLB header declares {} bytes but the file holds {}", length, size));
  std::uintmax_t at = 12;
  while (at + 8 <= length) {
    std::array<unsigned char, 8> chunk{};
    in.seekg(static_cast<std::streamoff>(at));
    if (!in.read(reinterpret_cast<char*>(chunk.data()), chunk.size())) break;
    const std::uint32_t chunk_length = little_endian_u32(chunk.data());
    if (at + 8 + chunk_length > length)
      refuse(where, path.string(),
             fmt::format("a GLB chunk at byte {} declares {} bytes; the file ends {} bytes later",
                         at, chunk_length, length - at - 8));
    if (std::memcmp(&chunk[4], "JSON", 4) == 0) {
      std::string text(chunk_length, '\0');
      if (!in.read(text.data(), static_cast<std::streamsize>(chunk_length))) break;
      const nlohmann::json gltf = nlohmann::json::parse(text, nullptr, false);
      if (!gltf.is_discarded()) check_gltf_json(gltf, path, where);
    }
    at += 8 + chunk_length;
  }
}

void check_gltf(const fs::path& path, const std::string& where) {
  std::ifstream in(path);
  const nlohmann::json gltf = nlohmann::json::parse(in, nullptr, false);
  // Not JSON: refused here, or Assimp would try its other formats' readers on it.
  if (gltf.is_discarded())
    refuse(where, path.string(),
           "a .gltf file is JSON and this one is not (expected a glTF 2.0 document; the binary "
           "form is .glb)");
  check_gltf_json(gltf, path, where);
}

// The fewest bytes a PLY property takes: its binary size, or in ASCII one digit and a
// separator. A list takes at least its count.
std::uintmax_t smallest_property(const std::string& type, bool ascii) {
  if (ascii) return 2;
  static const std::map<std::string, std::uintmax_t> sizes = {
      {"char", 1},  {"uchar", 1},   {"int8", 1},   {"uint8", 1},  {"short", 2}, {"ushort", 2},
      {"int16", 2}, {"uint16", 2},  {"int", 4},    {"uint", 4},   {"int32", 4}, {"uint32", 4},
      {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
  const auto found = sizes.find(type);
  return found == sizes.end() ? 1 : found->second;
}

// PLY: the header's elements times the fewest bytes each can take must fit in the file.
void check_ply(const fs::path& path, std::uintmax_t size, const std::string& where) {
  std::ifstream in(path, std::ios::binary);
  std::string line;
  bool ascii = true;
  struct Element {
    std::string name;
    std::uintmax_t count = 0, bytes = 0;
  };
  std::vector<Element> elements;
  std::uintmax_t header = 0;
  if (!std::getline(in, line) || (line != "ply" && line != "ply\r"))
    refuse(where, path.string(), "a .ply file begins with the line \"ply\" and this one does not");
  header += line.size() + 1;
  for (int lines = 0; std::getline(in, line) && lines < 10000; ++lines) {
    header += line.size() + 1;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    std::istringstream words(line);
    std::string word;
    words >> word;
    if (word == "format") {
      std::string format;
      words >> format;
      ascii = format == "ascii";
    } else if (word == "element") {
      Element e;
      if (!(words >> e.name >> e.count)) return;  // Assimp says
      elements.push_back(e);
    } else if (word == "property" && !elements.empty()) {
      std::string type;
      words >> type;
      if (type == "list") words >> type;  // the count's type
      elements.back().bytes += smallest_property(type, ascii);
    } else if (word == "end_header") {
      break;
    }
  }
  const std::uintmax_t body = size > header ? size - header : 0;
  std::uintmax_t needed = 0;
  for (const Element& e : elements) {
    const std::uintmax_t each = std::max<std::uintmax_t>(e.bytes, 1);
    if (e.count > body / each || needed + e.count * each > body)
      refuse(where, path.string(),
             fmt::format("the PLY header declares {} {} elements (at least {} bytes each) but the "
                         "file holds {} bytes after its header",
                         e.count, e.name, each, body));
    needed += e.count * each;
  }
}

}  // namespace

void check_mesh_file(const std::string& path, const std::string& where) {
  std::error_code ec;
  const std::uintmax_t size = fs::file_size(path, ec);
  if (ec) return;  // Assimp's own message says why it cannot be read
  const std::string ext = lower_extension(path);
  if (ext == ".glb") check_glb(path, size, where);
  if (ext == ".gltf") check_gltf(path, where);
  if (ext == ".ply") check_ply(path, size, where);
}

}  // namespace landsim::scenes::detail
