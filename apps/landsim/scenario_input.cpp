#include "scenario_input.h"

#include "core/input_error.h"
#include "scenes/default_scenario.h"

namespace landsim::app {

scenes::Scenario scenario_or_default(const std::string& path) {
  return path.empty() ? scenes::default_scenario() : scenes::load_scenario(path);
}

std::size_t view_index(const scenes::Scenario& s, const std::string& name) {
  if (name.empty()) return 0;
  for (std::size_t i = 0; i < s.views.size(); ++i) {
    if (s.views[i].name == name) return i;
  }
  throw InputError("--view: no view named \"" + name + "\" in " + s.source);
}

}  // namespace landsim::app
