#pragma once
// Runs a program as a user would, from a shell: its exit code, stdout and stderr.
#include <string>

#include "tests/support/temp_dir.h"

namespace landsim::testing {

struct ProgramResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// A shell command line; stderr goes through a file in `dir`.
ProgramResult run_command(const std::string& command, const TempDir& dir);
#ifdef LANDSIM_BINARY
// The landsim program under test with these arguments (suites that define LANDSIM_BINARY).
inline ProgramResult run_landsim(const std::string& args, const TempDir& dir) {
  return run_command(std::string(LANDSIM_BINARY) + " " + args, dir);
}
#endif

}  // namespace landsim::testing
