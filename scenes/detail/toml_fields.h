#pragma once
// Private to scenes/ (.cpp files only: toml++ is a heavy header). Reads the keys of one
// TOML table with validation, so every scenario error names file:line:column, the key, and
// what was expected; keys never read are reported as unknown.
#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec3.h"

namespace landsim::scenes::detail {

// An interval for numbers; open ends exclude the bound.
struct Range {
  double lo, hi;
  bool lo_open = false;
  bool hi_open = false;
  bool contains(double v) const;
  std::string describe() const;
};

class TableReader {
 public:
  // `path` names the table in messages ("terrain", "views[2]"); `file` the scenario file.
  TableReader(const toml::table& table, std::string path, std::string file);

  bool has(std::string_view key) const { return table_.contains(key); }
  double number(std::string_view key, Range range, std::optional<double> fallback = std::nullopt);
  std::optional<double> optional_number(std::string_view key, Range range);
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi,
                       std::optional<std::int64_t> fallback = std::nullopt);
  std::string string(std::string_view key, std::optional<std::string> fallback = std::nullopt);
  bool boolean(std::string_view key, bool fallback);
  // A size in bytes with a unit ("8 GB", "512 MiB"; SI units are powers of 1000), read by
  // CLI11's converter so the file and the command line agree.
  std::optional<std::uint64_t> byte_size(std::string_view key);
  // One of `choices`.
  std::string choice(std::string_view key, const std::vector<std::string>& choices,
                     std::string fallback);
  // An array of `N` numbers, each in `range`.
  std::vector<double> numbers(std::string_view key, std::size_t n, Range range,
                              std::optional<std::vector<double>> fallback = std::nullopt);
  std::optional<std::vector<double>> optional_numbers(std::string_view key, std::size_t n,
                                                      Range range);
  Vec3 vec3(std::string_view key, Range range = {-1e12, 1e12},
            std::optional<Vec3> fallback = std::nullopt);

  // Marks a key as known without reading it (its value was checked another way).
  void allow(std::string_view key) { read_.emplace(key); }

  // Refuses keys that were never asked for (typos must not pass silently).
  void finish() const;

  // "file:line:column: [table] key: message", pointing at the key's value when present.
  [[noreturn]] void fail(std::string_view key, const std::string& message) const;
  std::string location(const toml::node* node) const;
  const std::string& file() const { return file_; }

 private:
  const toml::node* node(std::string_view key);
  [[noreturn]] void missing(std::string_view key) const;

  const toml::table& table_;
  std::string path_;
  std::string file_;
  std::set<std::string, std::less<>> read_;
};

// Name of a TOML value's type, for "expected ..., got a string" messages.
std::string type_name(const toml::node& node);

// Error text for a file that fails to parse as TOML at all.
std::string parse_error_message(const toml::parse_error& e, const std::string& file);

}  // namespace landsim::scenes::detail
