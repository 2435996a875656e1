#include "trees/toml_reader.h"

#include <array>
#include <cstdint>

#include "core/input_error.h"

namespace landsim::trees {

void TomlReader::refuse(const toml::node& n, const std::string& key,
                        const std::string& expected) const {
  const auto& r = n.source();
  throw InputError(source_ + ":" + std::to_string(r.begin.line) + ":" +
                   std::to_string(r.begin.column) + ": " + key + ": expected " + expected);
}

double TomlReader::number(const toml::node& n, const std::string& key, double lo, double hi) const {
  const auto v = n.value<double>();
  if (!v || !(*v >= lo && *v <= hi))
    refuse(n, key, "a number from " + text(lo) + " to " + text(hi));
  return *v;
}

int TomlReader::integer(const toml::node& n, const std::string& key, int lo, int hi) const {
  const auto v = n.value<std::int64_t>();
  if (!n.is_integer() || !v || *v < lo || *v > hi)
    refuse(n, key, "a whole number from " + std::to_string(lo) + " to " + std::to_string(hi));
  return static_cast<int>(*v);
}

bool TomlReader::boolean(const toml::node& n, const std::string& key) const {
  if (!n.is_boolean()) refuse(n, key, "true or false");
  return *n.value<bool>();
}

Vec3 TomlReader::vector(const toml::node& n, const std::string& key) const {
  const toml::array* a = n.as_array();
  if (a == nullptr || a->size() != 3) refuse(n, key, "[x, y, z]");
  std::array<double, 3> c{};
  for (std::size_t i = 0; i < 3; ++i) c[i] = number(*a->get(i), key, -1e4, 1e4);
  return {c[0], c[1], c[2]};
}

const toml::table& TomlReader::table(const toml::node& n, const std::string& key) const {
  if (!n.is_table()) refuse(n, key, "a table");
  return *n.as_table();
}

const toml::array& TomlReader::tables(const toml::node& n, const std::string& key) const {
  const toml::array* a = n.as_array();
  if (a == nullptr || !a->is_array_of_tables()) refuse(n, key, "[[" + key + "]] tables");
  return *a;
}

std::string TomlReader::text(double v) {
  std::string s = std::to_string(v);
  s.erase(s.find_last_not_of('0') + 1);
  if (!s.empty() && s.back() == '.') s.pop_back();
  return s;
}

}  // namespace landsim::trees
