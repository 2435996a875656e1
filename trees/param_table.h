#pragma once
// Species parameters as read from a file, before a core interprets them: name -> value,
// with where each value was found, so that errors can point at the file and line.
#include <map>
#include <optional>
#include <sstream>
#include <string>

namespace landsim::trees {

struct RawParam {
  std::string text;              // the value as written (names such as "disc1" stay text)
  std::optional<double> number;  // set when the value is numeric
  std::string where;             // "file:line" (and ":column" when known)
};

using ParamTable = std::map<std::string, RawParam, std::less<>>;

// The number a parameter's text spells (blanks around it allowed), if it is one.
inline std::optional<double> param_number(const std::string& text) {
  std::istringstream in(text);
  double v = 0.0;
  in >> v;
  if (in.fail()) return std::nullopt;
  std::string rest;
  if (!in.eof() && (in >> rest, !rest.empty())) return std::nullopt;
  return v;
}

}  // namespace landsim::trees
