#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

#include "core/fnv_hash.h"
#include "core/input_error.h"
#include "featuremaps/placement.h"
#include "params/table_reader.h"
#include "scenes/scenario/scenario.h"

#include "scenes/scenario/detail/atmosphere_reader.h"
#include "scenes/scenario/detail/canopy_reader.h"
#include "scenes/scenario/detail/ground_reader.h"
#include "scenes/scenario/detail/haze_reader.h"
#include "scenes/scenario/detail/object_reader.h"
#include "scenes/scenario/detail/randomise_reader.h"
#include "scenes/scenario/detail/render_reader.h"
#include "scenes/scenario/detail/scenario_overrides.h"
#include "scenes/scenario/detail/sensor_reader.h"
#include "scenes/scenario/detail/sky_reader.h"
#include "scenes/scenario/detail/terrain_reader.h"
#include "scenes/scenario/detail/toml_tables.h"
#include "scenes/scenario/detail/vegetation_reader.h"
#include "scenes/scenario/detail/view_reader.h"

namespace landsim::scenes {

// Each table has its reader in detail/ (a file pair per table, or per kin of tables).
using namespace detail;

namespace {

void refuse_unknown_tables(const toml::table& root, const std::string& file) {
  static const std::set<std::string, std::less<>> kKnown{
      "terrain", "sun",    "views",  "render", "featuremaps", "species",
      "grass",   "ground", "wind",   "sky",    "haze",        "atmosphere",
      "objects", "bands",  "sensor", "canopy", "randomise"};
  for (auto&& [key, value] : root) {
    if (kKnown.count(key.str()) != 0) continue;
    const auto& b = key.source().begin;
    throw InputError(
        file + ":" + std::to_string(b.line) + ":" + std::to_string(b.column) +
        ": unknown table or key '" + std::string(key.str()) + "'" +
        params::did_you_mean(key.str(), std::vector<std::string>(kKnown.begin(), kKnown.end())) +
        " (expected terrain, featuremaps, species, grass, ground, wind, sun, sky, "
        "haze, atmosphere, views, render, objects, canopy, bands, sensor, randomise)");
  }
}

// [objects.place] view: one of the scenario's views.
void check_object_views(const Scenario& s) {
  for (const ObjectSettings& o : s.objects) {
    if (!o.siting) continue;
    std::vector<std::string> names;
    for (const ViewSettings& v : s.views) names.push_back("'" + v.name + "'");
    if (std::find(names.begin(), names.end(), "'" + o.siting->view + "'") == names.end())
      throw InputError(fmt::format("{}: [{}.place] view: no view is named '{}' (the views: {})",
                                   o.siting->location, o.path, o.siting->view,
                                   fmt::join(names, ", ")));
  }
}

}  // namespace

void require_views(const Scenario& s) {
  if (s.views.empty())
    throw InputError(s.source +
                     ": at least one [[views]] table is required to render (a periodic cell "
                     "without one can only be measured: landsim brf)");
}

void check_image_size(int width, int height, const std::string& where) {
  const std::string prefix = where.empty() ? "" : where + ": ";
  if (width < 1 || height < 1 || width > kMaxImageSide || height > kMaxImageSide) {
    throw InputError(prefix + "image size " + std::to_string(width) + " x " +
                     std::to_string(height) + ": each side must be from 1 to " +
                     std::to_string(kMaxImageSide));
  }
  if (double(width) * double(height) > kMaxImagePixels) {
    throw InputError(prefix + "image of " + std::to_string(width) + " x " + std::to_string(height) +
                     " pixels exceeds the limit of 100 million pixels");
  }
}

Scenario parse_scenario(std::string_view text, const std::string& source,
                        const std::string& base_dir, const std::vector<std::string>& sets) {
  toml::table root;
  try {
    root = toml::parse(text, source);
  } catch (const toml::parse_error& e) {
    throw InputError(params::parse_error_message(e, source));
  }
  if (root.contains("core"))
    throw InputError(source +
                     ": this is a species file (it names a tree core), not a scenario; a "
                     "scenario has [terrain], [sun] and [[views]] (landsim tree takes species "
                     "files)");
  apply_overrides(root, sets);
  refuse_unknown_tables(root, source);
  Scenario s;
  s.source = source;
  // Over the TOML as read, overrides applied, in toml++'s own layout: comments, spacing and
  // key order aside, so a scenario written back (Python's to_dict, from_dict) keeps its hash.
  std::ostringstream canonical;
  canonical << root;
  s.text_hash = fmt::format("{:016x}", fnv1a(canonical.str()));
  s.terrain = read_terrain(sub_table(root, "terrain", source, true), source, base_dir);
  s.sun = read_sun(sub_table(root, "sun", source, true), source);
  s.featuremaps = read_featuremaps(root, source, base_dir);
  s.species = read_species(root, source, base_dir);
  s.grass = read_grass(root, source);
  s.ground = read_ground(root, source, base_dir);
  // Where the i-th [[grass]] or [[species]] table stands, for the messages below.
  const auto where = [&](std::string_view key, std::size_t i) {
    const toml::array* a = root.get(key) != nullptr ? root.get(key)->as_array() : nullptr;
    const toml::node* first = a != nullptr && a->size() > i ? a->get(i) : root.get(key);
    const auto& b = first->source().begin;
    return source + ":" + std::to_string(b.line) + ":" + std::to_string(b.column);
  };
  // Vegetation grows where a feature map or its own cover says; with neither it would grow
  // nowhere.
  const bool maps =
      s.featuremaps && (!s.featuremaps->vegetation.empty() || !s.featuremaps->classes.empty());
  for (std::size_t i = 0; i < s.grass.size() && !maps; ++i)
    if (!s.grass[i].cover)
      throw InputError(where("grass", i) + ": [[grass]] type " + std::to_string(s.grass[i].type) +
                       " grows nowhere: give it a cover (\"everywhere\", a fraction, a "
                       "rectangle or a polygon) or add [featuremaps] vegetation or classes");
  for (std::size_t i = 0; i < s.species.size() && !maps; ++i)
    if (!s.species[i].cover)
      throw InputError(where("species", i) + ": [[species]] bit " +
                       std::to_string(s.species[i].bit) +
                       " grows nowhere: give it a cover (\"everywhere\", a fraction, a "
                       "rectangle or a polygon) or add [featuremaps] vegetation or classes");
  // Bands before the sensor, the sensor before the views: the channels share the bands'
  // layers, and each view may override the sensor.
  s.bands = read_bands(root, source, base_dir);
  s.sensor = read_sensor(root, source, base_dir, s.bands.size());
  // A periodic cell is measured from infinitely far (landsim brf): it needs no camera, and a
  // command that does says so (scenes::require_views).
  if (!(s.terrain.periodic && !root.contains("views")))
    s.views = read_views(root, source, s.sensor);
  s.render = read_render(sub_table(root, "render", source, false), source);
  s.wind = read_wind(sub_table(root, "wind", source, false), source);
  s.sky = read_sky(sub_table(root, "sky", source, false), source);
  s.haze = read_haze(root, source);
  read_atmosphere(root, source, s);
  s.objects = read_objects(root, source, base_dir);
  check_object_views(s);
  s.randomise = read_randomise(root, source, text, base_dir, sets);
  s.canopies = read_canopies(root, source, base_dir);
  return s;
}

bool has_cover(const Scenario& s) {
  return std::any_of(s.species.begin(), s.species.end(), [](const auto& k) { return k.cover; }) ||
         std::any_of(s.grass.begin(), s.grass.end(), [](const auto& g) { return g.cover; });
}

SensorSettings load_sensor(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file))
    throw InputError(file.string() + ": cannot open sensor file");
  std::ostringstream text;
  text << in.rdbuf();
  toml::table root;
  try {
    root = toml::parse(text.str(), file.string());
  } catch (const toml::parse_error& e) {
    throw InputError(params::parse_error_message(e, file.string()));
  }
  for (auto&& [key, value] : root)
    if (key.str() != "sensor") {
      const auto& b = key.source().begin;
      throw InputError(
          fmt::format("{}:{}:{}: unknown table or key '{}' (a sensor file holds "
                      "[sensor] alone)",
                      file.string(), b.line, b.column, key.str()));
    }
  std::optional<SensorSettings> s =
      read_sensor(root, file.string(), file.parent_path().string(), 0);
  if (!s) throw InputError(file.string() + ": no [sensor] table");
  return *s;
}

ScenarioText read_scenario_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in || std::filesystem::is_directory(file)) {
    throw InputError(file.string() + ": cannot open scenario file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return {text.str(), file.string(), file.parent_path().string()};
}

Scenario parse_scenario(const ScenarioText& t, const std::vector<std::string>& sets) {
  return parse_scenario(t.text, t.source, t.base_dir, sets);
}

std::string scenario_toml(const ScenarioText& t, const std::vector<std::string>& sets) {
  toml::table root;
  try {
    root = toml::parse(t.text, t.source);
  } catch (const toml::parse_error& e) {
    throw InputError(params::parse_error_message(e, t.source));
  }
  apply_overrides(root, sets);
  std::ostringstream out;
  out << root << "\n";
  return out.str();
}

Scenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& sets) {
  return parse_scenario(read_scenario_text(file), sets);
}

}  // namespace landsim::scenes
