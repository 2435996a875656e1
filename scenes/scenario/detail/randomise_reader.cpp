#include "scenes/scenario/detail/randomise_reader.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <sstream>

#include "core/input_error.h"

namespace landsim::scenes::detail {
namespace {

// Images one [randomise] set may hold (each is a scene built and rendered).
constexpr std::int64_t kMaxImages = 100000;

std::string where(const std::string& file, const toml::node& n) {
  const auto& b = n.source().begin;
  return fmt::format("{}:{}:{}", file, b.line, b.column);
}

[[noreturn]] void fail(const std::string& file, const toml::node& n, const std::string& key,
                       const std::string& message) {
  throw InputError(fmt::format("{}: [randomise] \"{}\": {}", where(file, n), key, message));
}

// A TOML value (not a table) as the text --set reads back to the same value.
std::string toml_text(const toml::node& n, const std::string& file, const std::string& key) {
  if (n.is_table()) fail(file, n, key, "choose: expected values (no tables)");
  std::ostringstream out;  // toml++'s own writer, strings double-quoted
  n.visit([&](auto&& v) { out << toml::toml_formatter{v, toml::format_flags::none}; });
  return out.str();
}

// A number or an array of numbers, as components; empty when it is neither.
std::optional<std::vector<double>> components(const toml::node& n) {
  std::vector<double> out;
  const auto one = [&](const toml::node& e) {
    const std::optional<double> v = e.value<double>();
    if (!v || !std::isfinite(*v)) return false;
    out.push_back(*v);
    return true;
  };
  if (const toml::array* a = n.as_array()) {
    if (a->empty()) return std::nullopt;
    for (const toml::node& e : *a)
      if (!one(e)) return std::nullopt;
  } else if (!one(n)) {
    return std::nullopt;
  }
  return out;
}

// The scenario's value at a --set key: tables by name, arrays of tables by index.
const toml::node* value_at(const toml::table& root, const std::string& key) {
  const toml::node* at = &root;
  std::size_t start = 0;
  while (at != nullptr) {
    const std::size_t dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? dot : dot - start);
    if (const toml::array* a = at->as_array()) {
      std::size_t i = 0;
      const auto [end, error] = std::from_chars(part.data(), part.data() + part.size(), i);
      at = error == std::errc() && end == part.data() + part.size() && i < a->size() ? a->get(i)
                                                                                     : nullptr;
    } else if (const toml::table* t = at->as_table()) {
      at = t->get(part);
    } else {
      return nullptr;
    }
    if (dot == std::string::npos) return at;
    start = dot + 1;
  }
  return nullptr;
}

RandomKey read_range(const toml::node& n, const std::string& file, const std::string& key) {
  RandomKey k;
  k.kind = RandomKey::Kind::range;
  const toml::array* a = n.as_array();
  const auto bad = [&] {
    fail(file, n, key,
         "range: expected [low, high] numbers, or [[low, ...], [high, ...]] for an array value");
  };
  if (a == nullptr || a->size() != 2) bad();
  const auto lo = components(*a->get(0)), hi = components(*a->get(1));
  if (!lo || !hi || lo->size() != hi->size()) bad();
  for (std::size_t c = 0; c < lo->size(); ++c)
    if (!((*lo)[c] <= (*hi)[c])) fail(file, n, key, "range: low above high");
  k.lo = *lo;
  k.hi = *hi;
  k.vector = a->get(0)->is_array();
  return k;
}

RandomKey read_jitter(const toml::node& n, const toml::table& root, const std::string& file,
                      const std::string& key) {
  RandomKey k;
  k.kind = RandomKey::Kind::jitter;
  const auto amount = components(n);
  if (!amount) fail(file, n, key, "jitter: expected a number or an array of numbers (+- each)");
  for (const double v : *amount)
    if (v < 0.0) fail(file, n, key, "jitter: expected amounts >= 0");
  const toml::node* own = value_at(root, key);
  const auto base = own != nullptr ? components(*own) : std::nullopt;
  if (!base)
    fail(file, n, key,
         "jitter: the scenario gives no number or array of numbers at this key to jitter about "
         "(use range)");
  if (amount->size() != 1 && amount->size() != base->size())
    fail(file, n, key,
         fmt::format("jitter: {} amounts for a value of {}", amount->size(), base->size()));
  k.base = *base;
  k.hi = amount->size() == 1 ? std::vector<double>(base->size(), (*amount)[0]) : *amount;
  k.lo = k.hi;
  k.vector = own->is_array();
  return k;
}

// One entry: { range = ... }, { choose = [...] } or { jitter = ... }.
RandomKey read_entry(const toml::table& spec, const toml::table& root, const std::string& file,
                     const std::string& key) {
  int kinds = 0;
  for (auto&& [name, value] : spec) {
    if (name.str() == "integer") continue;
    if (name.str() != "range" && name.str() != "choose" && name.str() != "jitter")
      fail(file, value, key,
           fmt::format("unknown key '{}' (expected one of range, choose, jitter; integer)",
                       name.str()));
    ++kinds;
  }
  if (kinds != 1) fail(file, spec, key, "expected one of range, choose or jitter");
  RandomKey k;
  if (const toml::node* r = spec.get("range")) k = read_range(*r, file, key);
  if (const toml::node* j = spec.get("jitter")) k = read_jitter(*j, root, file, key);
  if (const toml::node* c = spec.get("choose")) {
    const toml::array* a = c->as_array();
    if (a == nullptr || a->empty()) fail(file, *c, key, "choose: expected a non-empty array");
    k.kind = RandomKey::Kind::choose;
    for (const toml::node& e : *a) k.choices.push_back(toml_text(e, file, key));
  }
  if (const toml::node* i = spec.get("integer")) {
    if (!i->is_boolean() || k.kind != RandomKey::Kind::range)
      fail(file, *i, key, "integer: expected true or false, with range");
    k.integer = i->value_or(false);
    for (std::size_t c = 0; c < k.lo.size() && k.integer; ++c)
      if (k.lo[c] != std::floor(k.lo[c]) || k.hi[c] != std::floor(k.hi[c]))
        fail(file, *i, key, "integer: the range's bounds must be whole numbers");
  }
  k.key = key;
  k.location = where(file, spec);
  return k;
}

bool is_entry(const toml::table& t) {
  return t.contains("range") || t.contains("choose") || t.contains("jitter");
}

// Entries under `table`, their keys prefixed (nested tables read as dotted keys).
void read_entries(const toml::table& table, const std::string& prefix, const toml::table& root,
                  const std::string& file, std::vector<RandomKey>& out) {
  for (auto&& [name, value] : table) {
    const std::string key = prefix + std::string(name.str());
    if (prefix.empty() && (key == "images" || key == "seed")) continue;
    const toml::table* t = value.as_table();
    if (t == nullptr)
      fail(file, value, key,
           "expected { range = [low, high] }, { choose = [...] } or { jitter = amount }");
    if (is_entry(*t))
      out.push_back(read_entry(*t, root, file, key));
    else
      read_entries(*t, key + ".", root, file, out);
  }
}

}  // namespace

std::optional<RandomiseSettings> read_randomise(const toml::table& root, const std::string& file,
                                                std::string_view text, const std::string& base_dir,
                                                const std::vector<std::string>& sets) {
  const toml::node* n = root.get("randomise");
  if (n == nullptr) return std::nullopt;
  const toml::table* t = n->as_table();
  if (t == nullptr) throw InputError(where(file, *n) + ": [randomise]: expected a table");
  RandomiseSettings r;
  r.location = where(file, *n);
  if (const toml::node* images = t->get("images")) {
    const std::optional<std::int64_t> v = images->value<std::int64_t>();
    if (!images->is_integer() || !v || *v < 1 || *v > kMaxImages)
      throw InputError(fmt::format("{}: [randomise] images: expected an integer from 1 to {}",
                                   where(file, *images), kMaxImages));
    r.images = static_cast<int>(*v);
  } else {
    throw InputError(r.location +
                     ": [randomise] images: required key is missing (how many "
                     "images to draw)");
  }
  if (const toml::node* seed = t->get("seed")) {
    const std::optional<std::int64_t> v = seed->value<std::int64_t>();
    if (!seed->is_integer() || !v || *v < 0)
      throw InputError(where(file, *seed) + ": [randomise] seed: expected an integer >= 0");
    r.seed = static_cast<std::uint64_t>(*v);
  }
  read_entries(*t, "", root, file, r.keys);
  r.text = std::string(text);
  r.source = file;
  r.base_dir = base_dir;
  r.sets = sets;
  return r;
}

}  // namespace landsim::scenes::detail
