#pragma once
// `landsim init DIR`: writes a small working scenario (commented key by key) and every file
// it reads into a new folder, with paths relative to it, so it renders wherever it goes.
#include <string>

namespace CLI {
class App;
}

namespace landsim::app {

struct InitArgs {
  std::string dir;
};

CLI::App* add_init_command(CLI::App& app, InitArgs& args);
int run_init(const InitArgs& args);

}  // namespace landsim::app
