#include "featuremaps/class_mapping.h"

#include <spdlog/spdlog.h>
#include <toml++/toml.h>

#include <cmath>
#include <set>

#include "core/counter_rng.h"
#include "core/input_error.h"
#include "terrain/raster_files.h"

namespace landsim::featuremaps {
namespace {

std::string where(const std::string& file, const toml::node& n) {
  const auto& b = n.source().begin;
  return file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column);
}

int integer(const toml::table& t, std::string_view key, int lo, int hi, const std::string& file,
            std::optional<int> fallback) {
  const toml::node* n = t.get(key);
  if (n == nullptr) {
    if (fallback) return *fallback;
    throw InputError(where(file, t) + ": [[class]] " + std::string(key) +
                     ": required key is missing");
  }
  const auto v = n->value<std::int64_t>();
  if (!n->is_integer() || *v < lo || *v > hi) {
    throw InputError(where(file, *n) + ": [[class]] " + std::string(key) +
                     ": expected an integer from " + std::to_string(lo) + " to " +
                     std::to_string(hi));
  }
  return static_cast<int>(*v);
}

SpeciesShare read_share(const toml::node& node, const std::string& file) {
  const toml::table* t = node.as_table();
  if (t == nullptr)
    throw InputError(where(file, node) + ": species: expected { bit = N, fraction = F }");
  SpeciesShare s;
  s.bit = integer(*t, "bit", 0, kTreeBits - 1, file, std::nullopt);
  const toml::node* f = t->get("fraction");
  s.fraction = f != nullptr ? f->value<double>().value_or(-1.0) : 1.0;
  if (!(s.fraction >= 0.0 && s.fraction <= 1.0))
    throw InputError(where(file, node) + ": species: fraction must be from 0 to 1");
  for (auto&& [k, v] : *t) {
    if (k.str() != "bit" && k.str() != "fraction") {
      throw InputError(where(file, v) + ": species: unknown key '" + std::string(k.str()) +
                       "' (expected bit, fraction)");
    }
  }
  return s;
}

}  // namespace

ClassMapping load_class_mapping(const std::string& path) {
  const std::optional<std::string> text = terrain::read_text_file(path);
  if (!text) throw InputError(path + ": class mapping file not found");
  return parse_class_mapping(*text, path);
}

ClassMapping parse_class_mapping(std::string_view text, const std::string& path) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    const auto& b = e.source().begin;
    throw InputError(path + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) + ": " +
                     std::string(e.description()));
  }
  ClassMapping m;
  m.source = path;
  for (auto&& [k, v] : root) {
    if (k.str() != "class")
      throw InputError(where(path, v) + ": unknown key '" + std::string(k.str()) +
                       "' (expected [[class]] tables)");
  }
  const toml::array* classes = root["class"].as_array();
  if (classes == nullptr || !classes->is_array_of_tables())
    throw InputError(path + ": expected one or more [[class]] tables");
  std::set<int> seen;
  for (const toml::node& node : *classes) {
    const toml::table& t = *node.as_table();
    ClassRule rule;
    rule.value = integer(t, "value", -1000000, 1000000, path, std::nullopt);
    rule.grass = integer(t, "grass", 0, 3, path, 0);
    double total = 0.0;
    if (const toml::node* sp = t.get("species")) {
      const toml::array* a = sp->as_array();
      if (a == nullptr)
        throw InputError(where(path, *sp) + ": species: expected an array of { bit, fraction }");
      for (const toml::node& share : *a) {
        rule.species.push_back(read_share(share, path));
        total += rule.species.back().fraction;
      }
    }
    if (total > 1.0 + 1e-9)
      throw InputError(where(path, node) + ": species fractions of class " +
                       std::to_string(rule.value) + " add up to more than 1");
    for (auto&& [k, v] : t) {
      if (k.str() != "value" && k.str() != "grass" && k.str() != "species") {
        throw InputError(where(path, v) + ": [[class]] unknown key '" + std::string(k.str()) +
                         "' (expected value, species, grass)");
      }
    }
    if (!seen.insert(rule.value).second)
      throw InputError(where(path, node) + ": class " + std::to_string(rule.value) +
                       " is mapped twice");
    m.rules.push_back(rule);
  }
  return m;
}

VegetationMap build_vegetation_map(const terrain::ElevationGrid& classes,
                                   const ClassMapping& mapping, std::uint64_t seed) {
  std::vector<std::uint16_t> cells(static_cast<std::size_t>(classes.cols()) * classes.rows(), 0);
  std::set<int> unmapped;
  for (int r = 0; r < classes.rows(); ++r) {
    for (int c = 0; c < classes.cols(); ++c) {
      if (!classes.valid(c, r)) continue;
      const int value = static_cast<int>(std::lround(classes.at(c, r)));
      const ClassRule* rule = nullptr;
      for (const ClassRule& candidate : mapping.rules) {
        if (candidate.value == value) rule = &candidate;
      }
      if (rule == nullptr) {
        unmapped.insert(value);
        continue;
      }
      std::uint16_t cell = static_cast<std::uint16_t>(rule->grass << kTreeBits);
      const float u =
          CounterRng(seed, static_cast<std::uint64_t>(r) * 1000003u + static_cast<std::uint64_t>(c),
                     7)
              .uniform(0);
      double cumulative = 0.0;
      for (const SpeciesShare& s : rule->species) {
        cumulative += s.fraction;
        if (u < cumulative) {
          cell = static_cast<std::uint16_t>(cell | (1u << s.bit));
          break;
        }
      }
      cells[static_cast<std::size_t>(r) * classes.cols() + c] = cell;
    }
  }
  if (!unmapped.empty()) {
    std::string list;
    for (int v : unmapped) list += (list.empty() ? "" : ", ") + std::to_string(v);
    spdlog::warn("{}: classes without a rule get no vegetation: {}", mapping.source, list);
  }
  return VegetationMap(classes.cols(), classes.rows(), classes.transform(), std::move(cells));
}

}  // namespace landsim::featuremaps
