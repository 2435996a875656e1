#pragma once
// A subcommand of landsim: its CLI11 parser and what runs when it was given. main.cpp keeps
// the table of them; each command lives in its own <name>_command file pair, with its
// arguments, its CLI definition (add_*) and its body (run_*).
#include <functional>
#include <memory>

namespace CLI {
class App;
}

namespace landsim::app {

struct Command {
  CLI::App* cli = nullptr;
  std::function<int()> run;  // the exit code; throws InputError for bad input
};

// A command from its add_* and run_* functions; the arguments live as long as the command.
template <typename Args>
Command command(CLI::App& app, CLI::App* (*add)(CLI::App&, Args&), int (*run)(const Args&)) {
  auto args = std::make_shared<Args>();
  CLI::App* cli = add(app, *args);
  return {cli, [args, run] { return run(*args); }};
}

}  // namespace landsim::app
