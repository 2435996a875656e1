#pragma once
// Private to scenes/: reads [sensor] (docs/SENSOR.md) and a view's own `sensor` table over it,
// every key's unit and range checked, errors at the key's file:line; and a spectral response
// (a CSV file or a box), which [[bands]] and the sensor's channels share.
// Include from .cpp files only (toml++ is a heavy header).
#include <toml++/toml.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "params/table_reader.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// A band's or channel's `name`: 1-32 letters, digits, '_' or '-' (it names the EXR layer
// `layer` + name) and not in `taken` (else refused: "the name '<name>' " + `duplicate`); it is
// added to `taken`.
std::string read_layer_name(params::TableReader& r, const std::string& layer,
                            std::set<std::string>& taken, const std::string& duplicate);

// `response` (a CSV of wavelength, response, relative to `base_dir`) or `centre` and `width`
// (a box, nm); `description` says which ("box 630-690 nm", "response <path>").
std::vector<renderer::ResponsePoint> read_response(params::TableReader& r,
                                                   const std::string& base_dir,
                                                   std::string& description);

// [[bands]]: sensor bands, each a name and a response (a file, or a box); relative to `base_dir`.
std::vector<BandSettings> read_bands(const toml::table& root, const std::string& file,
                                     const std::string& base_dir);

// [sensor]; empty when the scenario has none. `bands`: the scenario's [[bands]] (channels and
// bands share the images' layer budget).
std::optional<SensorSettings> read_sensor(const toml::table& root, const std::string& file,
                                          const std::string& base_dir, std::size_t bands);

// The sensor of view `v` (its other keys read): [sensor]'s model with the view's `sensor`
// table over it (any key but the channels), its f-number and pixel pitch reconciled with the
// view's lens. Refuses a `sensor` table when the scenario has no [sensor].
std::optional<renderer::SensorModel> read_view_sensor(params::TableReader& view,
                                                      const std::optional<SensorSettings>& global,
                                                      const ViewSettings& v);

}  // namespace landsim::scenes::detail
