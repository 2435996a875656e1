#include "renderer/detail/number_table.h"

#include <charconv>
#include <stdexcept>
#include <string>

namespace landsim::renderer::detail {
namespace {

bool is_separator(char c) { return c == ',' || c == ' ' || c == '\t' || c == '\r'; }

// The numbers of one line; false if a field is not a number.
bool parse_line(std::string_view line, std::vector<double>& out) {
  out.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && is_separator(line[i])) ++i;
    if (i == line.size()) break;
    std::size_t end = i;
    while (end < line.size() && !is_separator(line[end])) ++end;
    double v = 0.0;
    const auto [stop, ec] = std::from_chars(line.data() + i, line.data() + end, v);
    if (ec != std::errc{} || stop != line.data() + end) return false;
    out.push_back(v);
    i = end;
  }
  return true;
}

}  // namespace

std::vector<std::vector<double>> number_rows(std::string_view text, const char* name) {
  std::vector<std::vector<double>> rows;
  std::vector<double> row;
  std::size_t start = 0;
  bool first = true;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    if (line.empty() || line.front() == '#') continue;
    const bool numeric = parse_line(line, row);
    if (!numeric && first) {
      first = false;  // a header
      continue;
    }
    first = false;
    if (!numeric)
      throw std::logic_error(std::string("embedded ") + name +
                             ": not numeric: " + std::string(line));
    if (!row.empty()) rows.push_back(row);
  }
  return rows;
}

}  // namespace landsim::renderer::detail
