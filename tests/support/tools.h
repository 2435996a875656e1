#pragma once
// External programs some tests compare against (POV-Ray). A test that needs one starts with
// LANDSIM_REQUIRE_TOOL("povray", "..."): without it the test is skipped, saying why and how
// to install it, except under CI (the environment variable CI set), which installs every
// tool (scripts/install-deps.sh): there a missing tool fails the test.
#include <gtest/gtest.h>

#include <cstdlib>

namespace landsim::testing {

// True when an executable of this name is on PATH.
bool tool_on_path(const char* name);

}  // namespace landsim::testing

#define LANDSIM_REQUIRE_TOOL(name, package)                                       \
  do {                                                                            \
    if (!landsim::testing::tool_on_path(name)) {                                  \
      if (std::getenv("CI") != nullptr) FAIL() << name << " is missing under CI"; \
      GTEST_SKIP() << name << " is not installed (apt install " << package        \
                   << "): this test compares landsim with it";                    \
    }                                                                             \
  } while (false)
