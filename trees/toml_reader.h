#pragma once
// Typed reads of species-file TOML values with one clear message on failure: the file, the
// line and column, the key, and what was expected (InputError, exit code 2). Shared by the
// cores that read their own tables (graph_paths, self_organizing).
#include <toml++/toml.h>

#include <string>

#include "core/vec3.h"

namespace landsim::trees {

class TomlReader {
 public:
  explicit TomlReader(const std::string& source) : source_(source) {}

  [[noreturn]] void refuse(const toml::node& n, const std::string& key,
                           const std::string& expected) const;

  double number(const toml::node& n, const std::string& key, double lo, double hi) const;
  int integer(const toml::node& n, const std::string& key, int lo, int hi) const;
  bool boolean(const toml::node& n, const std::string& key) const;
  Vec3 vector(const toml::node& n, const std::string& key) const;  // [x, y, z], |c| <= 1e4
  const toml::table& table(const toml::node& n, const std::string& key) const;
  // An array of tables ([[key]]).
  const toml::array& tables(const toml::node& n, const std::string& key) const;

  // Reads every key of table `t` (named `name`) with read(key, "name.key", value), which
  // returns false for a key it does not know; that key is refused, listing `known`.
  template <typename Read>
  void read_table(const toml::table& t, const std::string& name, const std::string& known,
                  Read&& read) const {
    for (auto&& [k, v] : t) {
      const std::string key = name + "." + std::string(k.str());
      if (!read(std::string(k.str()), key, v)) refuse(v, key, "one of " + known);
    }
  }

  const std::string& source() const { return source_; }
  // A number as a short decimal: 0.5, not 0.500000.
  static std::string text(double v);

 private:
  const std::string& source_;
};

}  // namespace landsim::trees
