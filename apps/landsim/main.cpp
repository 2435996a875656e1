// landsim: ray-traced offline landscape renderer. This file only parses the command line
// and maps outcomes to exit codes: 0 success, 2 bad input (one message), 1 internal error.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <iostream>
#include <new>

#include "core/input_error.h"
#include "degrade_command.h"
#include "discover_command.h"
#include "grow_command.h"
#include "info_command.h"
#include "mpi_session.h"
#include "plate_command.h"
#include "pov_command.h"
#include "render_command.h"
#include "tree_command.h"

namespace {

constexpr int kBadInput = 2;

// Logs and progress go to stderr, so stdout stays clean for --json. Under MPI every line
// names its rank.
void log_to_stderr(const std::string& rank) {
  auto logger = spdlog::stderr_color_mt("landsim");
  logger->set_pattern("landsim: " + rank + "%^%l%$: %v");
  spdlog::set_default_logger(logger);
}

}  // namespace

int main(int argc, char** argv) {
  const landsim::app::MpiSession session(argc, argv);
  log_to_stderr(session.label());
  CLI::App app{"landsim: ray-traced landscape renderer for scene simulation"};
  app.set_version_flag("--version", std::string("landsim ") + LANDSIM_VERSION);
  app.require_subcommand(1);
  landsim::app::RenderArgs render_args;
  CLI::App* render = landsim::app::add_render_command(app, render_args);
  landsim::app::TreeArgs tree_args;
  CLI::App* tree = landsim::app::add_tree_command(app, tree_args);
  landsim::app::InfoArgs info_args;
  CLI::App* info = landsim::app::add_info_command(app, info_args);
  landsim::app::ExportObjArgs export_obj_args;
  CLI::App* export_obj = landsim::app::add_export_obj_command(app, export_obj_args);
  landsim::app::PovArgs export_pov_args, crosscheck_args;
  CLI::App* export_pov = landsim::app::add_export_pov_command(app, export_pov_args);
  CLI::App* crosscheck = landsim::app::add_crosscheck_command(app, crosscheck_args);
  landsim::app::FeaturemapBuildArgs featuremap_args;
  CLI::App* featuremap_build = landsim::app::add_featuremap_command(app, featuremap_args);
  landsim::app::DiscoverArgs discover_args;
  CLI::App* discover = landsim::app::add_discover_command(app, discover_args);
  landsim::app::GrowArgs grow_args;
  CLI::App* grow = landsim::app::add_grow_command(app, grow_args);
  landsim::app::DegradeArgs degrade_args;
  CLI::App* degrade = landsim::app::add_degrade_command(app, degrade_args);
  landsim::app::PlateArgs plate_args;
  CLI::App* plate = landsim::app::add_plate_command(app, plate_args);

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }

  try {
    if (render->parsed()) return landsim::app::run_render(render_args);
    if (tree->parsed()) return landsim::app::run_tree(tree_args);
    if (info->parsed()) return landsim::app::run_info(info_args);
    if (export_pov->parsed()) return landsim::app::run_export_pov(export_pov_args);
    if (crosscheck->parsed()) return landsim::app::run_crosscheck(crosscheck_args);
    if (export_obj->parsed()) return landsim::app::run_export_obj(export_obj_args);
    if (featuremap_build->parsed()) return landsim::app::run_featuremap_build(featuremap_args);
    if (discover->parsed()) return landsim::app::run_discover(discover_args);
    if (grow->parsed()) return landsim::app::run_grow(grow_args);
    if (degrade->parsed()) return landsim::app::run_degrade(degrade_args);
    if (plate->parsed()) return landsim::app::run_plate(plate_args);
  } catch (const landsim::InputError& e) {
    std::cerr << "landsim: " << session.label() << "error: " << e.what() << "\n";
    // One rank failing fails the whole job: the others would wait for it forever.
    if (session.distributed()) session.abort(kBadInput);
    return kBadInput;
  } catch (const std::bad_alloc&) {
    std::cerr << "landsim: " << session.label()
              << "error: out of memory: the scene needs more than this process may use (its "
                 "estimate: landsim info; docs/PERFORMANCE.md \"Memory budget\")\n";
    if (session.distributed()) session.abort(1);
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "landsim: " << session.label() << "internal error: " << e.what() << "\n";
    if (session.distributed()) session.abort(1);
    return 1;
  }
  return 0;
}
