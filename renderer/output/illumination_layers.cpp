#include "renderer/output/illumination_layers.h"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "renderer/output/atmosphere_layers.h"

namespace landsim::renderer {
namespace {

int plane_of(const Film& film, const std::string& name) {
  const std::vector<std::string>& names = film.band_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) throw std::logic_error("the film holds no plane " + name);
  return static_cast<int>(it - names.begin());
}

}  // namespace

std::vector<std::string> illumination_layer_names() {
  return {"illumination.sunlit", "illumination.sky_view", "illumination.surface"};
}

int illumination_layer(IlluminationLayer layer, int band_count, bool atmosphere_layers) {
  const int atmosphere = atmosphere_layers ? kAtmosphereParts * (3 + band_count) : 0;
  return band_count + atmosphere + static_cast<int>(layer);
}

void finish_illumination_layers(Film& film) {
  const std::vector<std::string> names = illumination_layer_names();
  const std::vector<float>& surface = film.band_data(plane_of(film, names[2]));
  for (int layer = 0; layer < 2; ++layer) {
    std::vector<float>& plane =
        film.band_data(plane_of(film, names[static_cast<std::size_t>(layer)]));
    for (std::size_t i = 0; i < plane.size(); ++i)
      plane[i] = surface[i] > 0.0f ? std::min(plane[i] / surface[i], 1.0f)
                                   : std::numeric_limits<float>::quiet_NaN();
  }
}

}  // namespace landsim::renderer
