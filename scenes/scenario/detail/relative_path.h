#pragma once
// Private to scenes/: a path written in a scenario (or a file it reads) resolved against that
// file's folder, so a scenario renders as written from anywhere.
#include <filesystem>
#include <string>

namespace landsim::scenes::detail {

// `path` as it stands when absolute (or when there is no folder), else relative to `base_dir`;
// normalised either way.
inline std::string resolve(const std::string& base_dir, const std::string& path) {
  const std::filesystem::path p(path);
  if (p.is_absolute() || base_dir.empty()) return p.lexically_normal().string();
  return (std::filesystem::path(base_dir) / p).lexically_normal().string();
}

}  // namespace landsim::scenes::detail
