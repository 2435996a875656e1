#include "renderer/atmosphere/hosek_wilkie_tables.h"

#include "renderer/detail/number_table.h"

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace landsim::renderer {

// The CSV files of data/sky/, compiled in by renderer/CMakeLists.txt.
extern const std::string_view kHosekWilkieRgbCoefficientsCsv;
extern const std::string_view kHosekWilkieRgbRadianceCsv;
extern const std::string_view kHosekWilkieSolarRadianceCsv;
extern const std::string_view kHosekWilkieLimbDarkeningCsv;
extern const std::string_view kHosekWilkieSpectralCoefficientsCsv;
extern const std::string_view kHosekWilkieSpectralRadianceCsv;

namespace {

template <std::size_t N>
void fill(std::array<double, N>& to, std::string_view csv, int keys, int values_per_row,
          const char* name) {
  // The numeric fields of every data row after the header, in order (the files are ours and
  // fixed: a malformed one is a build error, reported loudly).
  std::vector<double> all;
  for (const auto& row : detail::number_rows(csv, name))
    all.insert(all.end(), row.begin(), row.end());
  const std::size_t per_row = static_cast<std::size_t>(keys + values_per_row);
  if (all.size() != N / static_cast<std::size_t>(values_per_row) * per_row)
    throw std::logic_error(std::string("embedded ") + name + ": unexpected number of values");
  std::size_t k = 0;
  for (std::size_t row = 0; row < all.size(); row += per_row)
    for (int v = 0; v < values_per_row; ++v) to[k++] = all[row + keys + v];
}

HosekWilkieTables load() {
  HosekWilkieTables t{};
  // The RGB files' first key is the channel letter: drop it before reading numbers.
  const auto strip_channel = [](std::string_view csv) {
    std::string out;
    out.reserve(csv.size());
    bool at_line_start = true;
    for (std::size_t i = 0; i < csv.size(); ++i) {
      if (at_line_start && i > 0 && (csv[i] == 'R' || csv[i] == 'G' || csv[i] == 'B')) {
        out += '0';  // a numeric stand-in; the files are ordered R, G, B
      } else {
        out += csv[i];
      }
      at_line_start = csv[i] == '\n';
    }
    return out;
  };
  const std::string coefficients = strip_channel(kHosekWilkieRgbCoefficientsCsv);
  const std::string radiance = strip_channel(kHosekWilkieRgbRadianceCsv);
  fill(t.coefficients, coefficients, 4, HosekWilkieTables::kParameters,
       "hosek_wilkie_rgb_coefficients.csv");
  fill(t.radiance, radiance, 4, 1, "hosek_wilkie_rgb_radiance.csv");
  fill(t.spectral_coefficients, kHosekWilkieSpectralCoefficientsCsv, 4,
       HosekWilkieTables::kParameters, "hosek_wilkie_spectral_coefficients.csv");
  fill(t.spectral_radiance, kHosekWilkieSpectralRadianceCsv, 4, 1,
       "hosek_wilkie_spectral_radiance.csv");
  fill(t.solar, kHosekWilkieSolarRadianceCsv, 4, 1, "hosek_wilkie_solar_radiance.csv");
  fill(t.limb_darkening, kHosekWilkieLimbDarkeningCsv, 1, 6, "hosek_wilkie_limb_darkening.csv");
  return t;
}

}  // namespace

const HosekWilkieTables& hosek_wilkie_tables() {
  static const HosekWilkieTables tables = load();
  return tables;
}

}  // namespace landsim::renderer
