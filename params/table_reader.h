#pragma once
// The one reader of TOML parameters (scenarios and species files alike; include it from .cpp
// files only: toml++ is a heavy header). Every key is declared where it is read, with its
// type, range and default; every error names file:line:column, the [table] and key, and what
// was expected, in one format; keys never read are reported as unknown (finish). A
// Declarations sink, when given, collects the declarations (docs are tested against them).
#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec3.h"

namespace landsim::params {

// An interval for numbers; open ends exclude the bound.
struct Range {
  double lo, hi;
  bool lo_open = false;
  bool hi_open = false;
  bool contains(double v) const;
  std::string describe() const;
};

// One declared key: the table's path ("graph", "volume[]"), the key, what it takes and its
// default as text ("" when required or when absence means "off").
struct KeyDeclaration {
  std::string table;
  std::string key;
  std::string expected;
  std::string fallback;
};
using Declarations = std::vector<KeyDeclaration>;

class TableReader {
 public:
  // `path` names the table in messages ("terrain", "views[2]"; "" for a file's top level);
  // `file` the file. Declarations go to `declared` when it is given.
  TableReader(const toml::table& table, std::string path, std::string file,
              Declarations* declared = nullptr);

  // The sub-table `key` (an empty one when absent and not required); refuses a non-table.
  TableReader table(std::string_view key, bool required = false);
  // The tables of the array `key` ([[key]]), each named "key[i]"; none when absent.
  std::vector<TableReader> tables(std::string_view key);
  // The raw value of `key` for shapes the typed reads do not cover (nullptr when absent),
  // declared with what it takes; errors inside it go through fail_at.
  const toml::node* value(std::string_view key, const std::string& expected,
                          const std::string& fallback = "");
  [[noreturn]] void fail_at(const toml::node& node, std::string_view key,
                            const std::string& message) const;

  bool has(std::string_view key) const { return table_->contains(key); }
  double number(std::string_view key, Range range, std::optional<double> fallback = std::nullopt);
  std::optional<double> optional_number(std::string_view key, Range range);
  // An angle written in degrees (within `degrees`), returned in radians; when the key is
  // absent the fallback (radians) is returned exactly as given.
  double angle(std::string_view key, Range degrees, double fallback_radians);
  std::int64_t integer(std::string_view key, std::int64_t lo, std::int64_t hi,
                       std::optional<std::int64_t> fallback = std::nullopt);
  std::string string(std::string_view key, std::optional<std::string> fallback = std::nullopt);
  bool boolean(std::string_view key, bool fallback);
  // A size in bytes with a unit ("8 GB", "512 MiB"; SI units are powers of 1000), read by
  // CLI11's converter so the file and the command line agree.
  std::optional<std::uint64_t> byte_size(std::string_view key);
  // One of `choices`.
  std::string choice(std::string_view key, const std::vector<std::string>& choices,
                     std::optional<std::string> fallback = std::nullopt);
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
  void declare(std::string_view key, const std::string& expected, const std::string& fallback);
  [[noreturn]] void missing(std::string_view key) const;
  std::string prefix(std::string_view key) const;  // "[table] key" or "key"

  const toml::table* table_;
  std::string path_;
  std::string file_;
  Declarations* declared_;
  std::set<std::string, std::less<>> read_;
};

// A number as a short decimal: 0.5, not 0.500000.
std::string format_number(double v);

// The candidate closest to a misspelt `name` (edit distance, case ignored), if one is close
// enough to be what was meant: " (did you mean 'x'?)", else "".
std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates);

// Name of a TOML value's type, for "expected ..., got a string" messages.
std::string type_name(const toml::node& node);

// Error text for a file that fails to parse as TOML at all.
std::string parse_error_message(const toml::parse_error& e, const std::string& file);

}  // namespace landsim::params
