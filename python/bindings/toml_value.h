#pragma once
// Python values as TOML and TOML as Python values: what `Scenario.set` and
// `Scenario.from_dict` take, and what `Scenario.to_dict` gives. Scenario keys then pass
// through the very reader (and validation) a scenario file does.
#include <pybind11/pybind11.h>

#include <string>

namespace landsim::python {

// The TOML text of `value` (a bool, number, string, list or dict): the value of a
// `--set key=value`. TypeError naming `key` for anything else (None, other objects).
std::string toml_value_text(const pybind11::handle& value, const std::string& key);

// `d` as a TOML document (TypeError naming the key of a value TOML cannot hold).
std::string toml_document(const pybind11::dict& d);

// A TOML document as dicts, lists and values.
pybind11::object toml_to_python(const std::string& toml_text, const std::string& source);

}  // namespace landsim::python
