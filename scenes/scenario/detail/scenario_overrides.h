#pragma once
// Scenario keys set from outside the file: `--set sun.elevation=30`, `--set views.0.fov=25`,
// `--set render.season=winter`. Each is applied to the parsed TOML before the scenario is
// read, so it passes the same validation as the file's own keys; a value is read as TOML
// (a number, boolean, array, quoted string) or else taken as a bare string. (Include from
// .cpp files only: toml++ is a heavy header.)
#include <toml++/toml.h>

#include <string>
#include <vector>

namespace landsim::scenes::detail {

// Applies each "key=value" to `root`: dotted tables, created where missing, and a number
// for the n-th table of an array of tables. The values' nodes carry "--set key=value" as
// their source, so messages about them name the override. InputError when malformed.
void apply_overrides(toml::table& root, const std::vector<std::string>& sets);

}  // namespace landsim::scenes::detail
