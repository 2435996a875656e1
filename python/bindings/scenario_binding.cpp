#include "python/bindings/scenario_binding.h"

#include <pybind11/stl.h>

#include <regex>

#include "core/input_error.h"
#include "python/bindings/toml_value.h"
#include "scenes/scenario/default_scenario.h"

namespace py = pybind11;

namespace landsim::python {
namespace {

py::object& scenario_error_class() {
  static py::object cls;
  return cls;
}

// `--set key=value` in the reader's messages reads as the call that set it.
std::string as_python_call(std::string message) {
  static const std::regex kSet("--set ([^=]+)=");
  return std::regex_replace(message, kSet, "set $1=");
}

// Reads `text` with `sets`, turning a refusal into ScenarioError (naming `key` when given).
scenes::Scenario read(const scenes::ScenarioText& text, const std::vector<std::string>& sets,
                      const std::string& key = {}) {
  try {
    return scenes::parse_scenario(text, sets);
  } catch (const InputError& e) {
    raise_scenario_error(e.what(), key);
  }
}

std::string repr(const PyScenario& s) {
  std::string views;
  for (const scenes::ViewSettings& v : s.scenario().views)
    views += (views.empty() ? "" : ", ") + v.name;
  return "<landsim.Scenario " + s.text().source + " (" + std::to_string(s.sets().size()) +
         " keys set; views: " + views + ")>";
}

}  // namespace

void raise_scenario_error(const std::string& message, const std::string& key) {
  const std::string text = as_python_call(message);
  // "<where>: [table] key: reason", "<where>: [table "name"] key: reason"
  static const std::regex kKey(R"(\[([A-Za-z_]+)[^\]]*\] ([A-Za-z_0-9.]+): (.*)$)");
  std::smatch m;
  std::string found_key = key, reason = text;
  if (std::regex_search(text, m, kKey)) {
    if (found_key.empty()) found_key = m[1].str() + "." + m[2].str();
    reason = m[3].str();
  }
  py::object error = scenario_error_class()(text);
  error.attr("key") = found_key.empty() ? py::object(py::none()) : py::object(py::str(found_key));
  error.attr("reason") = reason;
  PyErr_SetObject(scenario_error_class().ptr(), error.ptr());
  throw py::error_already_set();
}

PyScenario::PyScenario(scenes::ScenarioText text, std::vector<std::string> sets)
    : text_(std::move(text)), sets_(std::move(sets)), scenario_(read(text_, sets_)) {}

void PyScenario::set(const std::string& key, const py::handle& value) {
  std::vector<std::string> sets = sets_;
  sets.push_back(key + "=" + toml_value_text(value, key));
  scenario_ = read(text_, sets, key);
  sets_ = std::move(sets);
}

std::string PyScenario::to_toml() const {
  try {
    return scenes::scenario_toml(text_, sets_);
  } catch (const InputError& e) {
    raise_scenario_error(e.what());
  }
}

py::object PyScenario::to_dict() const { return toml_to_python(to_toml(), text_.source); }

void bind_scenario(py::module_& m) {
  scenario_error_class() = py::reinterpret_borrow<py::object>(
      PyErr_NewExceptionWithDoc("landsim.ScenarioError",
                                "A scenario, key or value landsim refuses: .key names the key "
                                "(or None), .reason says what was expected.",
                                PyExc_ValueError, nullptr));
  m.attr("ScenarioError") = scenario_error_class();
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      try {
        raise_scenario_error(e.what());
      } catch (py::error_already_set& raised) {
        raised.restore();  // the translator's way of raising: leave the error set
      }
    }
  });

  py::class_<PyScenario>(m, "Scenario", R"(A landsim scenario (docs/SCENARIO.md).

Scenario.load(path), Scenario.default(), Scenario.from_toml(text, base_dir) or
Scenario.from_dict(d, base_dir); then set keys with set("sun.elevation", 30). Every change is
validated at once (landsim.ScenarioError).)")
      .def_static(
          "load",
          [](const std::string& path) {
            try {
              return PyScenario(scenes::read_scenario_text(path), {});
            } catch (const InputError& e) {
              raise_scenario_error(e.what());
            }
          },
          py::arg("path"), "Reads a scenario file; relative paths in it resolve from its folder.")
      .def_static(
          "default", [] { return PyScenario(scenes::default_scenario_text(), {}); },
          "The embedded default scenario (`landsim render` without a file).")
      .def_static(
          "from_toml",
          [](const std::string& text, const std::string& base_dir) {
            return PyScenario({text, "<toml>", base_dir}, {});
          },
          py::arg("text"), py::arg("base_dir") = ".",
          "A scenario from TOML text; relative paths resolve from base_dir.")
      .def_static(
          "from_dict",
          [](const py::dict& d, const std::string& base_dir) {
            return PyScenario({toml_document(d), "<dict>", base_dir}, {});
          },
          py::arg("d"), py::arg("base_dir") = ".",
          "A scenario from a dict laid out as the TOML file (tables as dicts, arrays of tables "
          "as lists of dicts); relative paths resolve from base_dir.")
      .def(
          "set",
          [](PyScenario& s, const std::string& key, const py::handle& value) -> PyScenario& {
            s.set(key, value);
            return s;
          },
          py::arg("key"), py::arg("value"), py::return_value_policy::reference_internal,
          "Sets a key (\"sun.elevation\", \"views.0.fov\", \"render.season\") as --set does; "
          "ScenarioError, the scenario unchanged, when refused. Returns the scenario.")
      .def(
          "copy", [](const PyScenario& s) { return PyScenario(s); },
          "An independent copy (for batches of variations).")
      .def("__copy__", [](const PyScenario& s) { return PyScenario(s); })
      .def("__deepcopy__", [](const PyScenario& s, const py::dict&) { return PyScenario(s); })
      .def("to_toml", &PyScenario::to_toml, "The scenario as TOML, every key set included.")
      .def("to_dict", &PyScenario::to_dict, "The scenario as a dict (the TOML's layout).")
      .def_property_readonly("source", [](const PyScenario& s) { return s.text().source; })
      .def_property_readonly("base_dir", [](const PyScenario& s) { return s.text().base_dir; })
      .def_property_readonly(
          "hash", [](const PyScenario& s) { return s.scenario().text_hash; },
          "FNV-1a 64 of the text and the keys set (the images' scenario_hash)")
      .def_property_readonly("sets", &PyScenario::sets, "The keys set, as --set key=value")
      .def_property_readonly(
          "views",
          [](const PyScenario& s) {
            py::list names;
            for (const scenes::ViewSettings& v : s.scenario().views) names.append(v.name);
            return names;
          },
          "The views' names")
      .def_property_readonly(
          "frames", [](const PyScenario& s) { return s.scenario().render.frames; },
          "The frames' times (s)")
      .def("__repr__", &repr);
}

}  // namespace landsim::python
