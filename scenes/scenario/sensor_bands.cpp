#include "scenes/scenario/sensor_bands.h"

#include <charconv>
#include <cmath>

#include "core/input_error.h"
#include "renderer/spectra/spectrum.h"

namespace landsim::scenes {
namespace {

bool separator(char c) { return c == ',' || c == ' ' || c == '\t' || c == '\r' || c == ';'; }

// The fields of a line, split on separators.
std::vector<std::string_view> fields_of(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && separator(line[i])) ++i;
    std::size_t end = i;
    while (end < line.size() && !separator(line[end])) ++end;
    if (end > i) out.push_back(line.substr(i, end - i));
    i = end;
  }
  return out;
}

bool number_of(std::string_view field, double& v) {
  const auto [end, ec] = std::from_chars(field.data(), field.data() + field.size(), v);
  return ec == std::errc{} && end == field.data() + field.size() && std::isfinite(v);
}

}  // namespace

std::vector<renderer::ResponsePoint> parse_band_response(std::string_view text,
                                                         const std::string& file) {
  std::vector<renderer::ResponsePoint> points;
  std::size_t start = 0;
  int line_number = 0;
  bool header_allowed = true;
  while (start <= text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    const std::string_view line = text.substr(start, end - start);
    start = end + 1;
    ++line_number;
    const auto fields = fields_of(line);
    if (fields.empty() || fields.front().front() == '#') continue;
    const std::string where = file + ":" + std::to_string(line_number) + ": ";
    double nm = 0.0, response = 0.0;
    const bool numeric =
        fields.size() == 2 && number_of(fields[0], nm) && number_of(fields[1], response);
    if (!numeric && header_allowed && points.empty()) {
      header_allowed = false;  // a header line
      continue;
    }
    header_allowed = false;
    if (!numeric)
      throw InputError(where + "expected two numbers: wavelength in nm, relative response");
    if (response < 0.0) throw InputError(where + "the response must be >= 0");
    if (!points.empty() && nm < points.back().wavelength_nm)
      throw InputError(where + "wavelengths must not decrease (" + std::string(fields[0]) +
                       " nm after " + std::to_string(points.back().wavelength_nm) + " nm)");
    if (response > 0.0 && (nm < renderer::kFirstWavelength || nm > renderer::kLastWavelength))
      throw InputError(where + "a response at " + std::string(fields[0]) +
                       " nm: landsim's spectra cover 380-1020 nm only (give zero outside)");
    points.push_back({nm, response});
    if (end == text.size()) break;
  }
  if (points.size() < 2)
    throw InputError(file + ": a band response needs at least two rows (wavelength, response)");
  bool any = false;
  for (const auto& p : points) any = any || p.response > 0.0;
  if (!any) throw InputError(file + ": the response is zero everywhere");
  return points;
}

std::string photon_layer(const std::string& name) { return "photons." + name; }

}  // namespace landsim::scenes
