#include "render_command.h"

#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <csignal>
#include <filesystem>
#include <iostream>
#include <optional>

#include "core/input_error.h"
#include "core/process_memory.h"
#include "mpi_session.h"
#include "renderer/transport/render.h"
#include "scenario_input.h"
#include "scenes/image_set/image_set.h"
#include "scenes/scenario/randomise.h"
#include "scenes/scenario/render_choices.h"
#ifdef LANDSIM_HAVE_MPI
#include "distributed_render.h"
#endif

namespace landsim::app {
namespace {

// Command-line values win over the scenario's; a lone --width or --height keeps the aspect.
void apply_overrides(scenes::Scenario& s, const RenderArgs& args) {
  scenes::apply_render_choices(s, {.spp = args.spp,
                                   .threads = args.threads,
                                   .width = args.width,
                                   .height = args.height,
                                   .view = args.view});
}

}  // namespace

CLI::App* add_render_command(CLI::App& app, RenderArgs& args) {
  CLI::App* cmd = app.add_subcommand("render", "Path-trace the views of a scenario into EXR files");
  cmd->add_option("scenario", args.scenario, "Scenario TOML file (default: the embedded scene)");
  cmd->add_option("--out", args.out_dir, "Output directory")->capture_default_str();
  cmd->add_option("--view", args.view, "Render only the view with this name");
  cmd->add_option("--spp", args.spp, "Samples per pixel")->check(CLI::Range(1, scenes::kMaxSpp));
  cmd->add_option("--threads", args.threads, "Worker threads (0: every core)")
      ->check(CLI::Range(0, 1024));
  add_size_options(*cmd, args.width, args.height);
  cmd->add_flag("--json", args.json, "Print one JSON object on stdout");
  cmd->add_flag(
      "--resume", args.resume,
      "Continue an interrupted render in --out: keep its finished images, resume from checkpoints");
  cmd->add_option("--task-index", args.task_index,
                  "Render only image N of the set (frame-major), e.g. SLURM_ARRAY_TASK_ID")
      ->check(CLI::Range(0, 1000000));
  cmd->add_option("--max-memory", args.max_memory,
                  "Refuse a scene estimated to need more, e.g. 8GB (default: [render] "
                  "max_memory, else 80% of physical memory shared by the ranks on a node)")
      ->transform(CLI::AsSizeValue(true));
  cmd->add_flag("--check", args.check,
                "Render nothing: check every image of the set is in --out, write the manifest");
  add_set_option(*cmd, args.sets);
  return cmd;
}

namespace {

// SIGTERM (a batch system's time limit) or SIGINT (Ctrl-C) received during a render: the
// render stops at the next wave of tiles (or before building the next scene), writes its
// checkpoint and exits 128 + signal.
volatile std::sig_atomic_t g_stop_signal = 0;

extern "C" void request_stop(int signal) { g_stop_signal = signal; }

// Installs request_stop for the lifetime of a render, restoring the previous handlers.
class StopOnSignal {
 public:
  StopOnSignal()
      : term_(std::signal(SIGTERM, request_stop)), interrupt_(std::signal(SIGINT, request_stop)) {}
  ~StopOnSignal() {
    std::signal(SIGTERM, term_);
    std::signal(SIGINT, interrupt_);
  }
  StopOnSignal(const StopOnSignal&) = delete;
  StopOnSignal& operator=(const StopOnSignal&) = delete;

 private:
  void (*term_)(int);
  void (*interrupt_)(int);
};

// --check: every image of the set must be in the output directory; then the manifest.
int check_images(const scenes::Scenario& scenario, const std::filesystem::path& out_dir) {
  const std::vector<std::string> missing = scenes::check_image_set(scenario, out_dir);
  const std::size_t images =
      scenes::randomised_images(scenario) * scenario.render.frames.size() * scenario.views.size();
  if (!missing.empty()) {
    std::string list;
    for (const std::string& m : missing) list += (list.empty() ? "" : ", ") + m;
    spdlog::error("{}: {} of {} images missing: {}", out_dir.string(),
                  missing.size() / 2 + missing.size() % 2, images, list);
    return 1;
  }
  std::cout << fmt::format("{}: all {} images present, manifest written\n", out_dir.string(),
                           images);
  return 0;
}

nlohmann::json report_json(const scenes::ImageReport& r, const MpiSession* session) {
  nlohmann::json out = {{"path", r.exr.string()},
                        {"view", r.view},
                        {"frame_index", r.frame_index},  // as the manifest names them
                        {"time_s", r.time_s},
                        {"frame", r.time_s},  // = time_s, kept for scripts written before
                        {"exposure_ev100", r.exposure_ev100},
                        {"seconds", r.stats.seconds},
                        {"rays_per_second", r.stats.rays_per_second()}};
  if (!r.shared) {
    out["bvh_seconds"] = r.stats.setup_seconds;
    out["trace_seconds"] = r.stats.seconds - r.stats.setup_seconds;
  } else {
    out["ranks"] = session->size();
    out["communication_seconds"] = r.communication_seconds;
  }
  return out;
}

#ifdef LANDSIM_HAVE_MPI
// Every rank renders each image's tiles; rank 0 gets the film and writes (docs/CLUSTER.md).
scenes::SharedRender shared_render(const MpiSession& session) {
  scenes::SharedRender shared;
  shared.writer = session.rank() == 0;
  shared.render = [&session](const renderer::Renderer& renderer, const renderer::View& view,
                             const renderer::RenderOptions& options, scenes::ImageReport& report) {
    DistributedStats d;
    renderer::Film film = render_distributed(renderer, view, options, session, &d);
    report.stats.seconds = d.seconds;
    report.stats.rays = d.rays;
    report.communication_seconds = d.communication_seconds;
    if (session.rank() == 0)
      spdlog::info("{}: {:.2f} s, {:.3f} s in communication, {} of {} tiles on rank 0", view.name,
                   d.seconds, d.communication_seconds, d.tiles_by_rank0,
                   renderer::tile_count(view));
    return film;
  };
  return shared;
}
#endif

}  // namespace

int run_render(const RenderArgs& args) {
  scenes::Scenario scenario = scenario_or_default(args.scenario, args.sets);
  apply_overrides(scenario, args);
  const std::filesystem::path out_dir(args.out_dir);
  if (args.check) return check_images(scenario, out_dir);
  const MpiSession* session = current_session();
  scenes::ImageSetOptions options;
  options.out_dir = out_dir;
  options.resume = args.resume;
  if (args.task_index) options.task_index = static_cast<std::size_t>(*args.task_index);
  options.max_memory = args.max_memory;
  options.ranks_on_node = session != nullptr ? session->ranks_on_node() : 1;
#ifdef LANDSIM_HAVE_MPI
  std::optional<scenes::SharedRender> shared;
  if (session != nullptr && session->distributed()) {
    shared = shared_render(*session);
    options.shared = &*shared;
  }
#endif
  options.stop = [] { return g_stop_signal != 0; };
  options.written = [&args](const scenes::ImageReport& r) {
    if (!args.json)
      std::cout << fmt::format("{}: {} x {}, {} spp, {:.2f} s ({:.2f} s BVH), {:.2f} Mrays/s\n",
                               r.exr.string(), r.width, r.height, r.spp, r.stats.seconds,
                               r.stats.setup_seconds, r.stats.rays_per_second() / 1e6);
  };
  scenes::ImageSetResult result;
  {
    const StopOnSignal stop_on_signal;
    result = scenes::render_image_set(scenario, options);
  }
  if (result.stopped_at) {
    if (result.stopped_before_tracing)
      spdlog::error(
          "stopped by signal {} before rendering {} (nothing of it written); "
          "continue with --resume",
          static_cast<int>(g_stop_signal), *result.stopped_at);
    else
      spdlog::error("stopped by signal {} at {}: its checkpoint is in {}; continue with --resume",
                    static_cast<int>(g_stop_signal), *result.stopped_at, out_dir.string());
    return 128 + static_cast<int>(g_stop_signal);
  }
  const bool writer = session == nullptr || session->rank() == 0;
  if (!writer || !args.json) return 0;
  nlohmann::json reports = nlohmann::json::array();
  for (const scenes::ImageReport& r : result.images) reports.push_back(report_json(r, session));
  std::cout << nlohmann::json{{"images", reports},
                              {"scene_seconds", result.scene_seconds},
                              {"memory_estimate_bytes", result.memory_estimate_bytes},
                              {"peak_memory_bytes", peak_resident_bytes()}}
                   .dump()
            << "\n";
  return 0;
}

}  // namespace landsim::app
