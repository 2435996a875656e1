#pragma once
// Graph-paths species files: the TOML schema of docs/SPECIES.md ("graph_paths" core) read
// into generator Parameters. species.cpp reads the file and the shared keys (core, name,
// colours); this reads the core's own tables and refuses anything else.
#include <string>

#include "trees/graph_paths/generator.h"

namespace landsim::params {
class TableReader;
}

namespace landsim::trees::graph_paths {

// Reads the core's tables from a species file's top level (`root`; species.cpp reads the
// shared keys). Throws InputError naming the file, line and key, and what was expected; also
// refuses volumes that would need more than Parameters::max_nodes nodes at the given spacing.
Parameters read_parameters(params::TableReader& root, const std::string& source);

// Expected node count of a Poisson-disc fill (kNodesPerCubicSpacing, measured) of the
// primitives' summed volume: an upper estimate for overlapping unions.
double estimated_nodes(const Parameters& p);

}  // namespace landsim::trees::graph_paths
