#pragma once
// The Weber & Penn core names the trees' shared seeded stream in its own namespace.
#include "trees/random.h"

namespace landsim::trees::weber_penn {
using trees::Random;
}  // namespace landsim::trees::weber_penn
