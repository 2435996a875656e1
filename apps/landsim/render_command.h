#pragma once
// `landsim render [SCENARIO] [--out DIR] [--view NAME] [--spp N] [--threads N]
//                 [--width W] [--height H] [--json] [--resume] [--task-index N] [--check]
//                 [--max-memory SIZE]`
// Under mpirun every rank renders each image's tiles; rank 0 writes (docs/CLUSTER.md).
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace landsim::app {

struct RenderArgs {
  std::vector<std::string> sets;  // --set key=value overrides
  std::string scenario;           // empty: the embedded default scene
  std::string out_dir = "out";
  std::string view;  // empty: every view
  std::optional<int> spp;
  std::optional<int> threads;
  std::optional<int> width;
  std::optional<int> height;
  bool json = false;
  bool resume = false;  // continue from checkpoints left by a killed render
  // Render only this image of the set (frame-major: index = frame x views + view), for job
  // arrays; no manifest is written.
  std::optional<int> task_index;
  // Render nothing: check that every image of the set is in --out, then write the manifest.
  bool check = false;
  // Refuse, before building anything, a scene estimated to need more (bytes); overrides
  // [render] max_memory.
  std::optional<std::uint64_t> max_memory;
};

// Registers the subcommand; `args` is filled when it parses.
CLI::App* add_render_command(CLI::App& app, RenderArgs& args);

// Returns the process exit code; throws InputError for bad input.
int run_render(const RenderArgs& args);

}  // namespace landsim::app
