// landsim: ray-traced offline landscape renderer. This file holds the table of commands,
// parses the command line and maps outcomes to exit codes: 0 success, 2 bad input (one
// message), 1 internal error or a file the machine would not write.
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>
#include <CLI/CLI.hpp>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <new>
#include <vector>

#include "annotate_command.h"
#include "command.h"
#include "compare_command.h"
#include "core/input_error.h"
#include "core/input_warnings.h"
#include "core/module_loader.h"
#include "crosscheck_command.h"
#include "degrade_command.h"
#include "discover_command.h"
#include "export_obj_command.h"
#include "export_pov_command.h"
#include "featuremap_command.h"
#include "grow_command.h"
#include "brf_command.h"
#include "info_command.h"
#include "init_command.h"
#include "mpi_session.h"
#include "params/table_reader.h"
#include "plate_command.h"
#include "render_command.h"
#include "sense_command.h"
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
  // --strict anywhere on the line (before or after the command): warnings become errors.
  bool strict = false;
  app.add_flag("--strict", strict,
               "Refuse input that would only be warned about (a silent wrong scene): exit 2");
  app.fallthrough();
  namespace cmd = landsim::app;
  const std::vector<cmd::Command> commands = {
      cmd::command(app, cmd::add_render_command, cmd::run_render),
      cmd::command(app, cmd::add_tree_command, cmd::run_tree),
      cmd::command(app, cmd::add_info_command, cmd::run_info),
      cmd::command(app, cmd::add_brf_command, cmd::run_brf),
      cmd::command(app, cmd::add_export_obj_command, cmd::run_export_obj),
      cmd::command(app, cmd::add_export_pov_command, cmd::run_export_pov),
      cmd::command(app, cmd::add_crosscheck_command, cmd::run_crosscheck),
      cmd::command(app, cmd::add_compare_command, cmd::run_compare),
      cmd::command(app, cmd::add_annotate_command, cmd::run_annotate),
      cmd::command(app, cmd::add_sense_command, cmd::run_sense),
      cmd::command(app, cmd::add_featuremap_command, cmd::run_featuremap_build),
      cmd::command(app, cmd::add_discover_command, cmd::run_discover),
      cmd::command(app, cmd::add_grow_command, cmd::run_grow),
      cmd::command(app, cmd::add_degrade_command, cmd::run_degrade),
      cmd::command(app, cmd::add_plate_command, cmd::run_plate),
      cmd::command(app, cmd::add_init_command, cmd::run_init),
  };

  // A misspelt command: say which one was probably meant (CLI11 would only ask for one).
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> names;
    for (const CLI::App* sub : app.get_subcommands([](CLI::App*) { return true; }))
      names.push_back(sub->get_name());
    if (std::find(names.begin(), names.end(), argv[1]) == names.end()) {
      std::string list;
      for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
      std::cerr << "landsim: error: unknown command '" << argv[1] << "'"
                << landsim::params::did_you_mean(argv[1], names) << " (commands: " << list
                << "; landsim --help)\n";
      return kBadInput;
    }
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::Success& e) {
    return app.exit(e);  // --help, --version
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kBadInput;
  }

  landsim::input_warnings().strict = strict;
  landsim::input_warnings().sink = [](const std::string& m) { spdlog::warn("{}", m); };
  try {
    for (const cmd::Command& c : commands)
      if (c.cli->parsed()) return c.run();
  } catch (const landsim::InputError& e) {
    std::cerr << "landsim: " << session.label() << "error: " << e.what() << "\n";
    // One rank failing fails the whole job: the others would wait for it forever.
    if (session.distributed()) session.abort(kBadInput);
    return kBadInput;
  } catch (const landsim::ModuleError& e) {
    std::cerr << "landsim: " << session.label() << "error: " << e.what() << "\n";
    if (session.distributed()) session.abort(1);
    return 1;
  } catch (const std::bad_alloc&) {
    std::cerr << "landsim: " << session.label()
              << "error: out of memory: the scene needs more than this process may use (its "
                 "estimate: landsim info; docs/PERFORMANCE.md \"Memory budget\")\n";
    if (session.distributed()) session.abort(1);
    return 1;
  } catch (const std::filesystem::filesystem_error& e) {
    // The machine refused a file operation (an output name taken by a directory, a full or
    // read-only disk): the user's to fix, not landsim's bug. Outputs are atomic, so nothing
    // half-written is left.
    const std::filesystem::path& file = e.path2().empty() ? e.path1() : e.path2();
    std::cerr << "landsim: " << session.label() << "error: cannot write " << file.string() << ": "
              << e.code().message() << "\n";
    if (session.distributed()) session.abort(1);
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "landsim: " << session.label() << "internal error: " << e.what() << "\n";
    if (session.distributed()) session.abort(1);
    return 1;
  }
  return 0;
}
