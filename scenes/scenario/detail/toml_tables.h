#pragma once
// Private to scenes/scenario/: what every table's reader shares: the common ranges, the
// sub-tables and arrays of tables of a scenario's top level, and bounded lists of numbers.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <string>
#include <string_view>
#include <vector>

#include "core/vec3.h"
#include "params/table_reader.h"

namespace landsim::scenes::detail {

inline constexpr params::Range kUnit{0.0, 1.0};
inline constexpr params::Range kPositive{0.0, 1e12, true};

inline Vec3f to_vec3f(const Vec3& v) { return Vec3f(v); }

// Returns the sub-table `name`, or an empty one when absent; refuses a non-table.
const toml::table& sub_table(const toml::table& root, std::string_view name,
                             const std::string& file, bool required);

// An optional array of tables ([[key]]): null when absent, refused when something else.
const toml::array* tables(const toml::table& root, std::string_view key, const std::string& file);

// An array of numbers (at least `least`, at most `most`), each in `range`; empty when absent.
std::vector<double> number_list(params::TableReader& r, std::string_view key, std::size_t least,
                                std::size_t most, params::Range range);

}  // namespace landsim::scenes::detail
