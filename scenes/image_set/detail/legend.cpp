#include "scenes/image_set/detail/legend.h"

#include <nlohmann/json.hpp>

#include "renderer/output/film.h"

namespace landsim::scenes::detail {
namespace {

nlohmann::json object_classes() {
  // renderer::ObjectClass, by value.
  return {{"0", "sky"},
          {"1", "ground"},
          {"2", "bark"},
          {"3", "leaf"},
          {"4", "grass"},
          {"5", "scene object"},
          {"6", "none"},
          {"7", "plain (the ground beyond the elevation grid and over its nodata holes)"}};
}

nlohmann::json species(const Scenario& s) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < s.species.size(); ++k) {
    const SpeciesSettings& sp = s.species[k];
    out.push_back({{"id", k},
                   {"name", sp.species.name},
                   {"file", sp.species.source},
                   {"bit", sp.bit},
                   {"core", trees::core_name(sp.species)},
                   {"variants", sp.variants}});
  }
  // The [[canopy]] clouds follow the species (scenes/builder/detail/leaf_cloud): their leaves
  // carry these ids.
  for (std::size_t k = 0; k < s.canopies.size(); ++k) {
    const CanopySettings& c = s.canopies[k];
    out.push_back({{"id", s.species.size() + k},
                   {"name", c.name},
                   {"file", c.location},
                   {"core", "canopy"},
                   {"variants", c.generated ? c.generated->variants : 1}});
  }
  return out;
}

nlohmann::json objects(const Scenario& s) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t i = 0; i < s.objects.size(); ++i)
    out.push_back({{"id", i + 1}, {"name", s.objects[i].name}, {"file", s.objects[i].file}});
  return out;
}

}  // namespace

nlohmann::json legend(const Scenario& s) {
  const auto none = static_cast<std::uint64_t>(renderer::kNoId);
  return {
      {"object", {{"none", 6}, {"values", object_classes()}}},
      {"species", {{"none", none}, {"values", species(s)}}},
      {"instance",
       {{"none", none},
        {"values",
         "row i of landsim export-obj's <name>.instances.csv for the same scenario and "
         "frame (its instance column)"}}},
      {"target", {{"none", 0}, {"values", objects(s)}}},
      {"coverage", {{"none", 0}, {"values", "share of the pixel's samples that hit its target"}}},
      {"lod",
       {{"none", 0}, {"values", "tree detail step: 0 full, k the calibrated range 2^((k-1)/2) m"}}},
      {"Z", {{"none", "inf"}, {"values", "metres along the first sample's ray to its first hit"}}}};
}

}  // namespace landsim::scenes::detail
