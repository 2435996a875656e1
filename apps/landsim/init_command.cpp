#include "init_command.h"

#include <fmt/format.h>
#include <unistd.h>
#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <iostream>

#include "core/input_error.h"
#include "scenes/scenario/starter_scenario.h"

namespace landsim::app {
namespace {

namespace fs = std::filesystem;

// Every file into `dir` (created), or nothing: on failure the partial folder is removed.
void write_all(const fs::path& dir) {
  fs::create_directories(dir);
  for (const auto& [relative, content] : scenes::starter_files()) {
    const fs::path path = dir / relative;
    fs::create_directories(path.parent_path());
    std::ofstream out(path, std::ios::binary);
    out.write(content.data(), static_cast<std::streamsize>(content.size()));
    if (!out) throw InputError(path.string() + ": cannot write");
  }
}

}  // namespace

CLI::App* add_init_command(CLI::App& app, InitArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "init", "Write a small working scenario and the files it reads into a new folder");
  cmd->add_option("dir", args.dir, "The folder to create (it must not exist, or be empty)")
      ->required();
  return cmd;
}

int run_init(const InitArgs& args) {
  const fs::path dir = fs::absolute(args.dir).lexically_normal();
  std::error_code ec;
  if (fs::exists(dir, ec) && !(fs::is_directory(dir, ec) && fs::is_empty(dir, ec)))
    throw InputError(args.dir +
                     ": exists and is not an empty folder; landsim init writes a new "
                     "one (nothing was written)");
  // Written beside it under a temporary name and renamed when complete.
  const fs::path partial =
      dir.parent_path() / fmt::format(".{}.init-{}", dir.filename().string(), ::getpid());
  try {
    write_all(partial);
    if (fs::exists(dir)) fs::remove(dir);  // the empty folder the user made
    fs::rename(partial, dir);
  } catch (const std::exception& e) {
    fs::remove_all(partial, ec);
    if (dynamic_cast<const InputError*>(&e) != nullptr) throw;
    throw InputError(args.dir + ": cannot create the scenario folder: " + e.what());
  }
  std::cout << fmt::format(
      "{0}/scenario.toml written (with its elevation grid, land cover, class mapping and two "
      "species).\nRender it: landsim render {0}/scenario.toml --out {0}/out\n",
      args.dir);
  return 0;
}

}  // namespace landsim::app
