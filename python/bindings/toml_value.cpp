#include "python/bindings/toml_value.h"

#include <toml++/toml.h>

#include <sstream>

namespace py = pybind11;

namespace landsim::python {
namespace {

toml::table to_table(const py::dict& d, const std::string& path, bool inline_tables);
toml::array to_array(const py::handle& list, const std::string& path, bool inline_tables);

std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

// Calls `put` with `v` as the TOML value it stands for.
template <class Put>
void as_toml(const py::handle& v, const std::string& path, bool inline_tables, Put&& put) {
  if (py::isinstance<py::bool_>(v)) {
    put(v.cast<bool>());
  } else if (py::isinstance<py::int_>(v) || py::hasattr(v, "__index__")) {
    put(py::int_(py::reinterpret_borrow<py::object>(v)).cast<std::int64_t>());
  } else if (py::isinstance<py::float_>(v) || py::hasattr(v, "__float__")) {
    put(py::float_(py::reinterpret_borrow<py::object>(v)).cast<double>());
  } else if (py::isinstance<py::str>(v)) {
    put(v.cast<std::string>());
  } else if (py::isinstance<py::dict>(v)) {
    put(to_table(py::reinterpret_borrow<py::dict>(v), path, inline_tables));
  } else if (py::isinstance<py::list>(v) || py::isinstance<py::tuple>(v)) {
    put(to_array(v, path, inline_tables));
  } else {
    throw py::type_error(path + ": expected a bool, number, string, list or dict, got " +
                         std::string(py::str(v.get_type().attr("__name__"))));
  }
}

toml::table to_table(const py::dict& d, const std::string& path, bool inline_tables) {
  toml::table t;
  for (const auto& [k, v] : d) {
    if (!py::isinstance<py::str>(k))
      throw py::type_error(path + ": keys must be strings, got " +
                           std::string(py::str(k.get_type().attr("__name__"))));
    const std::string key = k.cast<std::string>();
    as_toml(v, child(path, key), inline_tables,
            [&](auto&& value) { t.insert_or_assign(key, std::forward<decltype(value)>(value)); });
  }
  t.is_inline(inline_tables && !path.empty());
  return t;
}

toml::array to_array(const py::handle& list, const std::string& path, bool inline_tables) {
  toml::array a;
  std::size_t i = 0;
  for (const py::handle v : list) {
    as_toml(v, path + "." + std::to_string(i++), inline_tables,
            [&](auto&& value) { a.push_back(std::forward<decltype(value)>(value)); });
  }
  return a;
}

py::object to_python(const toml::node& n);

py::object to_python(const toml::table& t) {
  py::dict d;
  for (auto&& [k, v] : t) d[py::str(std::string(k.str()))] = to_python(v);
  return d;
}

py::object to_python(const toml::node& n) {
  if (const toml::table* t = n.as_table()) return to_python(*t);
  if (const toml::array* a = n.as_array()) {
    py::list l;
    for (const toml::node& e : *a) l.append(to_python(e));
    return l;
  }
  if (const auto* s = n.as_string()) return py::str(s->get());
  if (const auto* i = n.as_integer()) return py::int_(i->get());
  if (const auto* f = n.as_floating_point()) return py::float_(f->get());
  if (const auto* b = n.as_boolean()) return py::bool_(b->get());
  std::ostringstream text;  // dates and times: as TOML writes them
  n.visit([&](auto&& v) { text << v; });
  return py::str(text.str());
}

}  // namespace

std::string toml_value_text(const py::handle& value, const std::string& key) {
  toml::table holder;
  as_toml(value, key, true,
          [&](auto&& v) { holder.insert_or_assign("v", std::forward<decltype(v)>(v)); });
  std::ostringstream text;
  text << holder;
  const std::string line = text.str();  // "v = <value>"
  return line.substr(line.find('=') + 2);
}

std::string toml_document(const py::dict& d) {
  std::ostringstream text;
  text << to_table(d, "", false) << "\n";
  return text.str();
}

py::object toml_to_python(const std::string& toml_text, const std::string& source) {
  return to_python(toml::parse(toml_text, source));
}

}  // namespace landsim::python
