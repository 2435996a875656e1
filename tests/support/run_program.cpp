#include "tests/support/run_program.h"

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>

namespace landsim::testing {

ProgramResult run_command(const std::string& command, const TempDir& dir) {
  const auto err_file = dir / "stderr.txt";
  const std::string cmd = command + " 2>" + err_file.string();
  ProgramResult r;
  FILE* pipe = ::popen(cmd.c_str(), "r");
  char buf[4096];
  std::size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) r.out.append(buf, n);
  const int status = ::pclose(pipe);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = read_file(err_file);
  std::filesystem::remove(err_file);
  return r;
}

}  // namespace landsim::testing
