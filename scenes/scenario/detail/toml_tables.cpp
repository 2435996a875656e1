#include "scenes/scenario/detail/toml_tables.h"

#include "core/input_error.h"

namespace landsim::scenes::detail {

const toml::table& sub_table(const toml::table& root, std::string_view name,
                             const std::string& file, bool required) {
  static const toml::table kEmpty;
  const toml::node* n = root.get(name);
  if (n == nullptr) {
    if (required)
      throw InputError(file + ": required table [" + std::string(name) + "] is missing");
    return kEmpty;
  }
  if (!n->is_table()) {
    const auto& b = n->source().begin;
    throw InputError(file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": " +
                     std::string(name) + ": expected a table, got " + params::type_name(*n));
  }
  return *n->as_table();
}

const toml::array* tables(const toml::table& root, std::string_view key, const std::string& file) {
  const toml::node* n = root.get(key);
  if (n == nullptr) return nullptr;
  const toml::array* a = n->as_array();
  if (a == nullptr || !a->is_array_of_tables()) {
    const auto& b = n->source().begin;
    throw InputError(file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": " +
                     std::string(key) + ": expected [[" + std::string(key) + "]] tables");
  }
  return a;
}

std::vector<double> number_list(params::TableReader& r, std::string_view key, std::size_t least,
                                std::size_t most, params::Range range) {
  const toml::node* n = r.value(key, "an array of numbers");
  if (n == nullptr) return {};
  const toml::array* a = n->as_array();
  if (a == nullptr || a->size() < least || a->size() > most)
    r.fail_at(*n, key,
              "expected an array of " + std::to_string(least) + " to " + std::to_string(most) +
                  " numbers");
  std::vector<double> out;
  for (const toml::node& e : *a) {
    const std::optional<double> v = e.value<double>();
    if (!v || !range.contains(*v)) r.fail_at(e, key, "expected numbers " + range.describe());
    out.push_back(*v);
  }
  return out;
}

}  // namespace landsim::scenes::detail
