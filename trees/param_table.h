#pragma once
// Species parameters as read from a file, before a core interprets them: name -> value,
// with where each value was found, so that errors can point at the file and line.
#include <map>
#include <optional>
#include <string>

namespace landsim::trees {

struct RawParam {
  std::string text;              // the value as written (names such as "disc1" stay text)
  std::optional<double> number;  // set when the value is numeric
  std::string where;             // "file:line" (and ":column" when known)
};

using ParamTable = std::map<std::string, RawParam, std::less<>>;

}  // namespace landsim::trees
