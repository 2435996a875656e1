#include "scenes/scenario/canopy.h"

#include <fmt/format.h>

#include <cmath>
#include <sstream>

#include "core/input_error.h"

namespace landsim::scenes {
namespace {

// The numbers of each content line of `text` (comments after '#', blank lines skipped):
// exactly `count` finite ones, else InputError at file:line naming `expected`. `take` gets
// them with the line number; at most `most` lines.
template <typename Take>
void for_each_row(std::string_view text, const std::string& file, std::size_t count,
                  std::size_t most, const char* expected, Take take) {
  std::size_t line_number = 0, rows = 0, start = 0;
  std::vector<double> values;
  while (start <= text.size()) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    std::string line(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (const std::size_t hash = line.find('#'); hash != std::string::npos) line.resize(hash);
    std::istringstream in(line);
    values.clear();
    std::string word;
    while (in >> word) {
      char* stop = nullptr;
      const double v = std::strtod(word.c_str(), &stop);
      if (stop != word.c_str() + word.size() || !std::isfinite(v))
        throw InputError(fmt::format("{}:{}: '{}' is not a number (expected {})", file, line_number,
                                     word, expected));
      values.push_back(v);
    }
    if (values.empty()) continue;
    if (values.size() != count)
      throw InputError(fmt::format("{}:{}: {} numbers, expected {}", file, line_number,
                                   values.size(), expected));
    if (++rows > most)
      throw InputError(fmt::format("{}:{}: more than {} rows", file, line_number, most));
    take(values, line_number);
  }
  if (rows == 0) throw InputError(fmt::format("{}: no rows (expected {})", file, expected));
}

}  // namespace

std::vector<LeafDisc> parse_leaf_discs(std::string_view text, const std::string& file) {
  std::vector<LeafDisc> out;
  for_each_row(
      text, file, 7, kMaxCloudDiscs, "radius x y z nx ny nz",
      [&](const std::vector<double>& v, std::size_t line) {
        const Vec3 n{v[4], v[5], v[6]};
        const double length = std::sqrt(dot(n, n));
        if (!(v[0] > 0.0) || !(length > 0.0))
          throw InputError(
              fmt::format("{}:{}: expected a positive radius and a non-zero normal", file, line));
        // A generated cloud's own bounds (its disc_radius and size keys).
        if (v[0] > kMaxDiscRadius)
          throw InputError(fmt::format("{}:{}: a disc radius of {} m: expected at most {} m", file,
                                       line, v[0], kMaxDiscRadius));
        const double reach = std::hypot(v[1], v[2], v[3]);  // no overflow
        if (!(reach <= kMaxCloudReach))
          throw InputError(
              fmt::format("{}:{}: a disc {} m from the cloud's origin: expected at most {} m (the "
                          "discs are relative to the origin each copy is placed at)",
                          file, line, reach, kMaxCloudReach));
        out.push_back(
            {Vec3f(Vec3{v[1], v[2], v[3]}), static_cast<float>(v[0]), Vec3f(n * (1.0 / length))});
      });
  return out;
}

std::vector<Vec3> parse_positions(std::string_view text, const std::string& file,
                                  std::vector<std::uint32_t>* lines) {
  std::vector<Vec3> out;
  for_each_row(text, file, 3, kMaxCanopyCopies, "x y z",
               [&](const std::vector<double>& v, std::size_t line) {
                 out.push_back({v[0], v[1], v[2]});
                 if (lines != nullptr) lines->push_back(static_cast<std::uint32_t>(line));
               });
  return out;
}

}  // namespace landsim::scenes
