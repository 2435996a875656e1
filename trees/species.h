#pragma once
// Species: a tree core and its parameters, loaded from a species file (TOML, or Arbaro XML
// for Weber & Penn). A variant is a species plus a seed; `generate` turns one into geometry.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include "trees/geometry.h"
#include "trees/graph_paths/generator.h"
#include "trees/harmonic/parameters.h"
#include "trees/measured_growth/parameters.h"
#include "trees/self_organizing/parameters.h"
#include "trees/skeleton.h"
#include "trees/tree_age.h"
#include "trees/weber_penn/parameters.h"

namespace landsim::params {
class TableReader;
struct KeyDeclaration;
using Declarations = std::vector<KeyDeclaration>;
}  // namespace landsim::params

namespace landsim::trees {

// The core is the alternative `parameters` holds.
struct Species {
  std::string name;
  std::string source;  // the file, for messages
  TreeColours colours;
  // The age of the file's tree and the height-age curve younger ones follow (not used by
  // measured growth, whose ages are its data's years).
  AgeCurve age;
  std::variant<weber_penn::Parameters, graph_paths::Parameters, self_organizing::Parameters,
               harmonic::Parameters, measured_growth::Parameters>
      parameters;
};

// The core's name in species files: "weber_penn", "graph_paths", ...
std::string core_name(const Species& species);
template <typename CoreParameters>
bool uses_core(const Species& species) {
  return std::holds_alternative<CoreParameters>(species.parameters);
}

// By extension: .toml (any core) or .xml (Arbaro's Weber & Penn format). Throws InputError
// naming the file, the line and the parameter.
Species load_species(const std::filesystem::path& file);

// A [leaf_optics] table (species files, and a scenario's [species.leaf_optics]): PROSPECT's
// structure and contents, each defaulting to the typical green leaf (trees/leaf_contents.h).
LeafContents read_leaf_contents(params::TableReader& t);
// Parses `text` as the format `source`'s extension names.
Species parse_species(std::string_view text, const std::string& source);
// `declared`, when given, collects every key the file's core declares (docs tests).
Species parse_species_toml(std::string_view text, const std::string& source,
                           params::Declarations* declared = nullptr);
Species parse_arbaro_xml(std::string_view text, const std::string& source);

struct TreeOptions {
  std::uint64_t seed = 1;
  double time = 0.0;  // seconds, for wind sway
  double wind_speed = 0.0;
  double wind_gust = 0.0;
  double quality = 1.0;  // leaf quality factor, (0, 1]
  double age = -1.0;     // years (< 0: the species file's tree; trees/tree_age.h)
  // Seeds the sway's phases; 0: `seed` (a variant's phase groups share its structure and
  // differ here).
  std::uint64_t sway_seed = 0;
};

struct TreeStats {
  std::vector<int> stems_per_level;  // clones included
  int clones = 0;
  int leaves = 0;
  double height = 0.0;        // metres, highest point above the base
  double crown_radius = 0.0;  // metres, farthest point from the vertical through the base
};

struct Tree {
  TreeGeometry geometry;
  TreeStats stats;
};

// The core's skeleton for `options` (seed, quality, age), calm: what `generate` sways and
// meshes.
TreeSkeleton core_skeleton(const Species& species, const TreeOptions& options);

Tree generate(const Species& species, const TreeOptions& options);

// A self-organising species' growth steps for a tree of `age` years (< 0: the file's own;
// clamped with a warning as generate does).
int self_organizing_steps(const Species& species, double age);

// The same tree (options' seed) at each of `ages` (years): as generate with options.age set
// to each, the self-organising core growing once and recovering the younger trees from its
// time stamps.
std::vector<Tree> generate_ages(const Species& species, const TreeOptions& options,
                                const std::vector<double>& ages);

}  // namespace landsim::trees
