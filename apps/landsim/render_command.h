#pragma once
// `landsim render [SCENARIO] [--out DIR] [--view NAME] [--spp N] [--threads N]
//                 [--width W] [--height H] [--json]`
#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct RenderArgs {
  std::string scenario;  // empty: the embedded default scene
  std::string out_dir = "out";
  std::string view;  // empty: every view
  std::optional<int> spp;
  std::optional<int> threads;
  std::optional<int> width;
  std::optional<int> height;
  bool json = false;
  bool resume = false;  // continue from checkpoints left by a killed render
};

// Registers the subcommand; `args` is filled when it parses.
CLI::App* add_render_command(CLI::App& app, RenderArgs& args);

// Returns the process exit code; throws InputError for bad input.
int run_render(const RenderArgs& args);

}  // namespace landsim::app
