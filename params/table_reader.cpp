#include "params/table_reader.h"

#include <CLI/Error.hpp>
#include <CLI/Validators.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/input_error.h"

namespace landsim::params {
namespace {

// Edit distance with case ignored, a swap of neighbours counting as one edit (optimal
// string alignment): "sede" is one edit from "seed".
std::size_t edit_distance(std::string_view a, std::string_view b) {
  const auto same = [&](std::size_t i, std::size_t j) {
    return std::tolower(static_cast<unsigned char>(a[i])) ==
           std::tolower(static_cast<unsigned char>(b[j]));
  };
  std::vector<std::vector<std::size_t>> d(a.size() + 1, std::vector<std::size_t>(b.size() + 1));
  for (std::size_t i = 0; i <= a.size(); ++i) d[i][0] = i;
  for (std::size_t j = 0; j <= b.size(); ++j) d[0][j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i)
    for (std::size_t j = 1; j <= b.size(); ++j) {
      d[i][j] = std::min(
          {d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (same(i - 1, j - 1) ? 0 : 1)});
      if (i > 1 && j > 1 && same(i - 1, j - 2) && same(i - 2, j - 1))
        d[i][j] = std::min(d[i][j], d[i - 2][j - 2] + 1);
    }
  return d[a.size()][b.size()];
}

}  // namespace

std::string did_you_mean(std::string_view name, const std::vector<std::string>& candidates) {
  // Close enough: a third of the name's letters wrong at most (at least one, at most three).
  const std::size_t limit = std::clamp<std::size_t>(name.size() / 3, 1, 3);
  std::string best;
  std::size_t best_distance = limit + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = edit_distance(name, c);
    if (d < best_distance) {
      best = c;
      best_distance = d;
    }
  }
  return best.empty() ? "" : " (did you mean '" + best + "'?)";
}

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

bool Range::contains(double v) const {
  if (!std::isfinite(v)) return false;
  const bool above = lo_open ? v > lo : v >= lo;
  const bool below = hi_open ? v < hi : v <= hi;
  return above && below;
}

std::string Range::describe() const {
  if (lo_open && hi >= 1e12) return "greater than " + format_number(lo);
  if (hi >= 1e12) return "at least " + format_number(lo);
  std::string s =
      "from " + format_number(lo) + (lo_open ? " (exclusive)" : "") + " to " + format_number(hi);
  if (hi_open) s += " (exclusive)";
  return s;
}

std::string type_name(const toml::node& node) {
  switch (node.type()) {
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a float";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::date:
      return "a date";
    case toml::node_type::time:
      return "a time";
    case toml::node_type::date_time:
      return "a date-time";
    default:
      return "nothing";
  }
}

std::string parse_error_message(const toml::parse_error& e, const std::string& file) {
  const auto& where = e.source().begin;
  return file + ":" + std::to_string(where.line) + ":" + std::to_string(where.column) +
         ": not valid TOML: " + std::string(e.description());
}

TableReader::TableReader(const toml::table& table, std::string path, std::string file,
                         Declarations* declared)
    : table_(&table), path_(std::move(path)), file_(std::move(file)), declared_(declared) {}

TableReader TableReader::table(std::string_view key, bool required) {
  static const toml::table kEmpty;
  const std::string path = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (required) missing(key);
    return TableReader(kEmpty, path, file_, declared_);
  }
  if (!n->is_table()) fail(key, "expected a table, got " + type_name(*n));
  return TableReader(*n->as_table(), path, file_, declared_);
}

std::vector<TableReader> TableReader::tables(std::string_view key) {
  std::vector<TableReader> out;
  const std::string path = path_.empty() ? std::string(key) : path_ + "." + std::string(key);
  const toml::node* n = node(key);
  if (n == nullptr) return out;
  const toml::array* a = n->as_array();
  if (a == nullptr || !a->is_array_of_tables())
    fail(key, "expected [[" + std::string(key) + "]] tables, got " + type_name(*n));
  for (std::size_t i = 0; i < a->size(); ++i)
    out.emplace_back(*a->get(i)->as_table(), path + "[" + std::to_string(i) + "]", file_,
                     declared_);
  return out;
}

const toml::node* TableReader::value(std::string_view key, const std::string& expected,
                                     const std::string& fallback) {
  declare(key, expected, fallback);
  return node(key);
}

void TableReader::declare(std::string_view key, const std::string& expected,
                          const std::string& fallback) {
  if (declared_ == nullptr) return;
  // Tables of an array declare under "name[]", whichever element read them.
  std::string table = path_;
  if (const auto open = table.rfind('['); open != std::string::npos && table.back() == ']')
    table = table.substr(0, open) + "[]";
  for (const KeyDeclaration& d : *declared_)
    if (d.table == table && d.key == key) return;
  declared_->push_back({table, std::string(key), expected, fallback});
}

std::string TableReader::prefix(std::string_view key) const {
  return path_.empty() ? std::string(key) : "[" + path_ + "] " + std::string(key);
}

std::string TableReader::location(const toml::node* node) const {
  const toml::source_region& src = node != nullptr ? node->source() : table_->source();
  // A value set from the command line (scenes/scenario/detail/scenario_overrides) names itself.
  if (src.path != nullptr && src.path->rfind("--set ", 0) == 0) return *src.path;
  if (src.begin.line == 0) return file_;
  return file_ + ":" + std::to_string(src.begin.line) + ":" + std::to_string(src.begin.column);
}

void TableReader::fail(std::string_view key, const std::string& message) const {
  const toml::node* n = table_->get(key);
  throw InputError(location(n) + ": " + prefix(key) + ": " + message);
}

void TableReader::fail_at(const toml::node& node, std::string_view key,
                          const std::string& message) const {
  throw InputError(location(&node) + ": " + prefix(key) + ": " + message);
}

void TableReader::missing(std::string_view key) const {
  throw InputError(location(nullptr) + ": " + prefix(key) + ": required key is missing");
}

const toml::node* TableReader::node(std::string_view key) {
  read_.emplace(key);
  return table_->get(key);
}

double TableReader::number(std::string_view key, Range range, std::optional<double> fallback) {
  declare(key, "a number " + range.describe(), fallback ? format_number(*fallback) : "");
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (!fallback) missing(key);
    return *fallback;
  }
  if (!n->is_number())
    fail(key, "expected a number " + range.describe() + ", got " + type_name(*n));
  const double v = n->value<double>().value();
  if (!range.contains(v)) {
    fail(key, "expected a number " + range.describe() + ", got " + format_number(v));
  }
  return v;
}

double TableReader::angle(std::string_view key, Range degrees, double fallback_radians) {
  constexpr double kDegree = std::numbers::pi / 180.0;
  const double v = number(key, degrees, fallback_radians / kDegree);
  return has(key) ? v * kDegree : fallback_radians;
}

std::optional<double> TableReader::optional_number(std::string_view key, Range range) {
  if (!has(key)) {
    declare(key, "a number " + range.describe(), "");
    read_.emplace(key);
    return std::nullopt;
  }
  return number(key, range);
}

std::int64_t TableReader::integer(std::string_view key, std::int64_t lo, std::int64_t hi,
                                  std::optional<std::int64_t> fallback) {
  declare(key, "an integer from " + std::to_string(lo) + " to " + std::to_string(hi),
          fallback ? std::to_string(*fallback) : "");
  const toml::node* n = node(key);
  const std::string expected =
      "expected an integer from " + std::to_string(lo) + " to " + std::to_string(hi);
  if (n == nullptr) {
    if (!fallback) missing(key);
    return *fallback;
  }
  if (!n->is_integer()) fail(key, expected + ", got " + type_name(*n));
  const std::int64_t v = n->value<std::int64_t>().value();
  if (v < lo || v > hi) fail(key, expected + ", got " + std::to_string(v));
  return v;
}

std::string TableReader::string(std::string_view key, std::optional<std::string> fallback) {
  declare(key, "a string", fallback ? "\"" + *fallback + "\"" : "");
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (!fallback) missing(key);
    return *fallback;
  }
  if (!n->is_string()) fail(key, "expected a string, got " + type_name(*n));
  return std::string(*n->value<std::string_view>());
}

std::optional<std::uint64_t> TableReader::byte_size(std::string_view key) {
  declare(key, "a size", "");
  const toml::node* n = node(key);
  if (n == nullptr) return std::nullopt;
  std::string text;
  if (n->is_integer()) text = std::to_string(*n->value<std::int64_t>());
  if (n->is_string()) text = std::string(*n->value<std::string_view>());
  std::string error = text.empty() ? "empty" : "";
  try {
    if (error.empty()) error = CLI::AsSizeValue(true)(text);
  } catch (const CLI::ValidationError& e) {
    error = e.what();
  }
  if (!error.empty() || text.front() == '-')
    fail(key, "expected a size such as \"8 GB\" or \"512 MiB\" (or a number of bytes)");
  const std::uint64_t bytes = std::stoull(text);
  if (bytes == 0) fail(key, "expected a size above zero");
  return bytes;
}

bool TableReader::boolean(std::string_view key, bool fallback) {
  declare(key, "true or false", fallback ? "true" : "false");
  const toml::node* n = node(key);
  if (n == nullptr) return fallback;
  if (!n->is_boolean()) fail(key, "expected true or false, got " + type_name(*n));
  return *n->value<bool>();
}

std::string TableReader::choice(std::string_view key, const std::vector<std::string>& choices,
                                std::optional<std::string> fallback) {
  std::string names;
  for (const std::string& c : choices) names += (names.empty() ? "\"" : ", \"") + c + "\"";
  declare(key, "one of " + names, fallback ? "\"" + *fallback + "\"" : "");
  const std::string v = string(key, fallback);
  for (const std::string& c : choices) {
    if (c == v) return v;
  }
  std::string list;
  for (const std::string& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
  fail(key, "expected one of " + list + ", got \"" + v + "\"");
}

std::vector<double> TableReader::numbers(std::string_view key, std::size_t count, Range range,
                                         std::optional<std::vector<double>> fallback) {
  std::string fallback_text;
  if (fallback)
    for (double v : *fallback)
      fallback_text += (fallback_text.empty() ? "" : ", ") + format_number(v);
  declare(key, "an array of " + std::to_string(count) + " numbers, each " + range.describe(),
          fallback ? "[" + fallback_text + "]" : "");
  const toml::node* n = node(key);
  if (n == nullptr) {
    if (!fallback) missing(key);
    return *fallback;
  }
  const std::string expected =
      "expected an array of " + std::to_string(count) + " numbers, each " + range.describe();
  const toml::array* a = n->as_array();
  if (a == nullptr || a->size() != count) {
    fail(key,
         expected + ", got " + (a ? "an array of " + std::to_string(a->size()) : type_name(*n)));
  }
  std::vector<double> out;
  for (const toml::node& item : *a) {
    if (!item.is_number()) fail(key, expected + ", got an element that is " + type_name(item));
    const double v = item.value<double>().value();
    if (!range.contains(v)) fail(key, expected + ", got " + format_number(v));
    out.push_back(v);
  }
  return out;
}

std::optional<std::vector<double>> TableReader::optional_numbers(std::string_view key,
                                                                 std::size_t n, Range range) {
  if (!has(key)) {
    declare(key, "an array of " + std::to_string(n) + " numbers, each " + range.describe(), "");
    read_.emplace(key);
    return std::nullopt;
  }
  return numbers(key, n, range);
}

Vec3 TableReader::vec3(std::string_view key, Range range, std::optional<Vec3> fallback) {
  std::optional<std::vector<double>> fb;
  if (fallback) fb = std::vector<double>{fallback->x, fallback->y, fallback->z};
  const std::vector<double> v = numbers(key, 3, range, fb);
  return {v[0], v[1], v[2]};
}

void TableReader::finish() const {
  for (auto&& [key, value] : *table_) {
    if (read_.count(key.str()) != 0) continue;
    std::string known;
    for (const std::string& k : read_) known += (known.empty() ? "" : ", ") + k;
    const std::string hint =
        did_you_mean(key.str(), std::vector<std::string>(read_.begin(), read_.end()));
    throw InputError(location(&value) + ": " + (path_.empty() ? "" : "[" + path_ + "] ") +
                     "unknown key '" + std::string(key.str()) + "'" + hint +
                     " (expected one of: " + known + ")");
  }
}

}  // namespace landsim::params
