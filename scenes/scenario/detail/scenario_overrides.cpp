#include "scenes/scenario/detail/scenario_overrides.h"

#include <charconv>

#include "core/input_error.h"

namespace landsim::scenes::detail {
namespace {

std::vector<std::string> split(const std::string& key) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t dot = key.find('.'); dot != std::string::npos; dot = key.find('.', start)) {
    parts.push_back(key.substr(start, dot - start));
    start = dot + 1;
  }
  parts.push_back(key.substr(start));
  return parts;
}

// The value as TOML, its source named `source`; a bare word (winter) as a string.
toml::table parsed(const std::string& value, const std::string& source) {
  try {
    return toml::parse("v = " + value, source);
  } catch (const toml::parse_error&) {
  }
  std::string quoted = "\"";
  for (const char c : value) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  try {
    return toml::parse("v = " + quoted + "\"", source);
  } catch (const toml::parse_error&) {
    throw InputError(source + ": the value is neither TOML nor a plain word");
  }
}

// The table `part` names inside `at` (created if missing): a key, or an index into an
// array of tables.
toml::table& step_into(toml::node& at, const std::string& part, const std::string& source) {
  if (toml::array* a = at.as_array()) {
    std::size_t index = 0;
    const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), index);
    if (error != std::errc() || end != part.data() + part.size() || index >= a->size() ||
        !(*a)[index].is_table())
      throw InputError(source + ": '" + part + "' is not an index of the " +
                       std::to_string(a->size()) + " tables of this array (0 to " +
                       std::to_string(a->size() - 1) + ")");
    return *(*a)[index].as_table();
  }
  toml::table& t = *at.as_table();
  if (!t.contains(part)) t.insert(part, toml::table{});
  toml::node* next = t.get(part);
  if (!next->is_table()) throw InputError(source + ": '" + part + "' is a value, not a table");
  return *next->as_table();
}

}  // namespace

void apply_overrides(toml::table& root, const std::vector<std::string>& sets) {
  for (const std::string& set : sets) {
    const std::string source = "--set " + set;
    const std::size_t eq = set.find('=');
    if (eq == std::string::npos || eq == 0)
      throw InputError(source + ": expected key=value, e.g. --set sun.elevation=30");
    const std::vector<std::string> parts = split(set.substr(0, eq));
    toml::node* at = &root;
    for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
      if (parts[i].empty()) throw InputError(source + ": an empty part in the key");
      if (at->is_table() && at->as_table()->contains(parts[i]) &&
          at->as_table()->get(parts[i])->is_array_of_tables()) {
        at = at->as_table()->get(parts[i]);  // the next part indexes it
        continue;
      }
      at = &step_into(*at, parts[i], source);
    }
    toml::table* target = at->as_table();
    if (target == nullptr)
      throw InputError(source + ": '" + parts.back() +
                       "' needs a table index first (e.g. views.0.fov)");
    toml::table value = parsed(set.substr(eq + 1), source);
    target->insert_or_assign(parts.back(), std::move(*value.get("v")));
  }
}

}  // namespace landsim::scenes::detail
