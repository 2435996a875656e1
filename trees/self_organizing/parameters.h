#pragma once
// Parameters of the self-organising core (TreeSketch, Longay et al. 2012, on Palubicki et
// al. 2009 and Runions et al. 2007). Lengths are metres unless a comment says "internode
// lengths"; angles are radians here and degrees in species files (docs/SELF_ORGANIZING.md).
#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec3.h"
#include "trees/self_organizing/bending.h"
#include "trees/self_organizing/envelope.h"
#include "trees/self_organizing/lasso.h"

namespace landsim::params {
class TableReader;
}

namespace landsim::trees::self_organizing {

// A brush stroke: the brush moves along the polyline, `points_per_step` points per step from
// `start_step`, and drops markers in its sphere that live `max_age` steps.
struct StrokePoint {
  Vec3 position;
  double radius = 0.5;
};

struct BrushStroke {
  std::vector<StrokePoint> points;
  int start_step = 1;
  double points_per_step = 1.0;
  int markers_per_step = 60;
  int max_age = 6;
};

struct SpaceParameters {
  double occupancy = 2.0;          // r, internode lengths: markers this near a bud are consumed
  double perception = 4.0;         // d, internode lengths: the perception cone reaches r + d
  double perception_angle = 1.57;  // zeta, the cone's full opening angle
  int autonomous_markers = 0;      // markers each bud drops in its cone every step (live 1 step)
};

// Shadow propagation (Palubicki 2009): a metamer adds a * b^-q to the voxels q layers below
// it, in a square spreading by q; a bud's light is max(C - s + a, 0).
struct LightParameters {
  double full = 1.0;  // C
  double a = 0.05;    // small enough that a dense crown darkens gradually (docs/SELF_ORGANIZING.md)
  double b = 2.0;     // > 1
  int depth = 6;      // q_max
  double voxel = 1.0;        // internode lengths
  double sensitivity = 1.0;  // kappa: Q = b_g * L^kappa
};

struct VigourParameters {
  double alpha = 2.0;           // v at the base = alpha * Q of the whole tree
  double apical_control = 0.5;  // lambda
  double shedding = 0.0;        // Th: a branch with less vigour per internode is shed
  int max_shoot = 3;            // n_max: the most vigorous bud's shoot, in metamers
};

// The control ellipse of gravimorphism: semi-axes s_v (vertical) and s_p (horizontal), its
// centre e_v above the bud. A bud's factor is the distance from the bud to the ellipse along
// the bud's direction: e_v > 0 favours upward buds (epitony), e_v < 0 downward ones
// (hypotony), s_p > s_v sideways ones (amphitony).
struct Gravimorphism {
  double vertical = 1.0;
  double horizontal = 1.0;
  double offset = 0.0;
};

struct DirectionParameters {
  double heading = 1.0;          // weight of the current heading H
  double tropism = 0.2;          // weight of the tropism vector T
  double environment = 0.3;      // weight of the environment direction E
  double set_point = 0.0;        // theta of branches: T's angle from the vertical (0 up,
                                 // pi/2 level, > pi/2 down)
  double trunk_set_point = 0.0;  // theta of the trunk (order 0): upright unless set
  double branching = 0.785;      // psi: a lateral bud's angle to its internode
  double deflection = 0.0;       // delta: the axis turns away from each new lateral bud
  double phyllotaxis = 2.40;     // divergence between successive lateral buds
  double noise = 0.05;           // random turn per metamer
};

// Pipe model d^n = sum d_i^n. A constraint fixes the width of one internode (by index in
// growth order, 0 the trunk's first); n is then solved for its subtree.
struct WidthConstraint {
  std::uint32_t internode = 0;
  double width = 0.1;
};

struct WidthParameters {
  double tip = 0.004;
  double exponent = 2.0;
  std::vector<WidthConstraint> constraints;
};

struct LeafParameters {
  int age = 2;  // steps: internodes younger than this carry a leaf
  double length = 0.08;
  double width = 0.05;
};

// TreeSketch section 4 "Pruning": the branch from the living internode nearest `at` (at
// that step; never the seedling's first) up is removed, and the widths below it are as if it
// had never grown; with `stub`, the internode stays as a stub that keeps its width (the
// paper's width constraint below the cut). A point, not an internode number, so that the
// cut holds for every seed of the species.
struct Pruning {
  int step = 1;  // before this step's growth
  Vec3 at;       // the cut: the internode nearest this point
  bool stub = false;
  std::string where;  // "file:line:column: [[prune]]", for errors found while growing
};

// Growth rules changed from a step on (TreeSketch section 3: the modeler changes parameters
// as the tree grows): the vigour, gravimorphism and direction parameters in effect from
// `from_step`, each phase starting from the rules before it. With `select`, TreeSketch's
// selective growth mode: the bud nearest that point when the phase begins is selected, and
// only the branch originating at it competes for markers and grows; every bud still removes
// the markers in its occupancy zone. A point, not a bud's index, so that the selection
// holds for every seed of the species.
struct GrowthPhase {
  int from_step = 1;
  VigourParameters vigour;
  Gravimorphism gravimorphism;
  DirectionParameters direction;
  bool selective = false;
  Vec3 select;
};

struct Parameters {
  // True if a shoot may not reach p at `step`: some envelope or lasso confines growth by then
  // and p lies in none of them.
  bool confined_out(const Vec3& p, int step) const;

  int steps = 20;
  double internode_length = 0.1;
  SpaceParameters space;
  LightParameters light;
  VigourParameters vigour;
  Gravimorphism gravimorphism;
  DirectionParameters direction;
  WidthParameters width;
  LeafParameters leaves;
  Envelope envelope;
  std::vector<Lasso> lassos;  // of the whole tree or of parts, each from its step
  std::vector<BrushStroke> strokes;
  std::vector<Pruning> prunings;
  std::vector<GrowthPhase> phases;  // by ascending from_step
  std::vector<Bend> bends;          // edits of the grown tree, in order (bending.h)
  // Growth beyond this is refused (InputError): a tree of 100,000 internodes is five times the
  // largest shipped species (so_shedding, 21,196) and some 2 million triangles, far more than
  // TreeSketch's trees, grown at interactive rates on a tablet (Longay et al. 2012, section 1).
  // The refusal costs what growing that far costs: about 1.4 s and 150 MB at worst measured.
  std::size_t max_internodes = 100000;
  std::size_t max_markers = 10000000;  // markers held at once beyond this (280 MB): refused
  // Autonomous markers the buds drop in one step beyond this: refused. 35 times the most a
  // shipped species drops (57,354); the buds multiply each step, so the step before the
  // refusal held a few times fewer and the refusal comes within a second.
  std::size_t max_autonomous_markers = 2000000;
  std::string source;  // the species file, for errors found while growing
};

// The core's own tables of a species file (docs/SPECIES.md); throws InputError naming the
// file, line, key and what was expected.
Parameters read_parameters(params::TableReader& root, const std::string& source);

}  // namespace landsim::trees::self_organizing
