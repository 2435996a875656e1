#pragma once
// `landsim.Scenario`: a scenario's text, the keys set on it, and the scenario they read as.
// Every change is read again at once through the scenario reader, so a bad key or value is
// refused where it is set, with the reader's own message (landsim.ScenarioError).
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include "scenes/scenario/scenario.h"

namespace landsim::python {

class PyScenario {
 public:
  PyScenario(scenes::ScenarioText text, std::vector<std::string> sets);

  // Sets `key` (dotted, array tables by index: "views.0.fov") to `value`; on a refusal the
  // scenario stays as it was.
  void set(const std::string& key, const pybind11::handle& value);
  std::string to_toml() const;
  pybind11::object to_dict() const;

  const scenes::Scenario& scenario() const { return scenario_; }
  const scenes::ScenarioText& text() const { return text_; }
  const std::vector<std::string>& sets() const { return sets_; }

 private:
  scenes::ScenarioText text_;
  std::vector<std::string> sets_;  // "key=value", in the order they were set
  scenes::Scenario scenario_;
};

// Raises landsim.ScenarioError for `message` (an InputError's): .key and .reason parsed from
// the reader's "<where>: [table] key: reason", or `key` when given.
[[noreturn]] void raise_scenario_error(const std::string& message, const std::string& key = {});

void bind_scenario(pybind11::module_& m);

}  // namespace landsim::python
