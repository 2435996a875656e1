#include "sense_command.h"

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>

#include "core/input_error.h"
#include "scenes/image_set/sensor_output.h"
#include "scenes/scenario/scenario.h"

namespace landsim::app {

CLI::App* add_sense_command(CLI::App& app, SenseArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "sense",
      "Apply a sensor again to an image set's photon layers: digital numbers without tracing "
      "(docs/SENSOR.md)");
  cmd->add_option("set", args.set, "An image set rendered with [sensor]")->required();
  cmd->add_option("--sensor", args.sensor,
                  "A TOML file with a [sensor] table (default: the sensor each image was "
                  "rendered with)");
  cmd->add_option("--noise-seed", args.noise_seed, "Another noise seed")
      ->check(CLI::Range(std::uint64_t{0}, std::uint64_t{INT64_MAX}));
  cmd->add_option("--exposure-time", args.exposure_time, "Another exposure time, seconds")
      ->check(CLI::Range(1e-9, 3600.0));
  cmd->add_option("--out", args.out,
                  "The sensed set's folder: the EXRs and previews linked, the new digital "
                  "numbers and manifest (default: SET_sensed)");
  cmd->add_flag("--in-place", args.in_place,
                "Rewrite the set's own digital numbers and manifest instead");
  cmd->add_flag("--json", args.json, "Print the files written as one JSON object on stdout");
  return cmd;
}

// SET_sensed beside the set ("out/" and "out" alike give "out_sensed").
std::filesystem::path sensed_folder(const std::string& set) {
  std::filesystem::path p = std::filesystem::path(set).lexically_normal();
  if (p.filename().empty()) p = p.parent_path();
  return p.string() + "_sensed";
}

int run_sense(const SenseArgs& args) {
  scenes::SenseOptions o;
  if (!args.sensor.empty()) o.sensor = scenes::load_sensor(args.sensor).model;
  o.noise_seed = args.noise_seed;
  o.exposure_time_s = args.exposure_time;
  if (args.in_place && !args.out.empty())
    throw InputError("--out " + args.out + " and --in-place: give one");
  if (!args.in_place)
    o.out = args.out.empty() ? sensed_folder(args.set) : std::filesystem::path(args.out);
  const std::vector<std::filesystem::path> written = scenes::sense_image_set(args.set, o);
  if (args.json) {
    nlohmann::json files = nlohmann::json::array();
    for (const auto& f : written) files.push_back(f.string());
    std::cout << nlohmann::json{{"written", files}}.dump() << "\n";
  } else {
    for (const auto& f : written) std::cout << f.string() << "\n";
    std::cout << fmt::format("{}: {} images sensed\n", o.out.empty() ? args.set : o.out.string(),
                             written.size());
  }
  return 0;
}

}  // namespace landsim::app
