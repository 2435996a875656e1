#pragma once
// `landsim sense SET [--sensor FILE] [--noise-seed N] [--exposure-time S] [--json]`:
// applies a sensor again to a stored image set without tracing it again (docs/SENSOR.md):
// another noise, another exposure, or another sensor on the channels the set rendered.
#include <cstdint>
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct SenseArgs {
  std::string set;
  std::string sensor;  // a TOML file with [sensor]; empty: the one each image was rendered with
  std::optional<std::uint64_t> noise_seed;
  std::optional<double> exposure_time;
  std::string out;        // empty: SET_sensed
  bool in_place = false;  // rewrite the set itself
  bool json = false;
};

CLI::App* add_sense_command(CLI::App& app, SenseArgs& args);
int run_sense(const SenseArgs& args);

}  // namespace landsim::app
