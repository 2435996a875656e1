#include "trees/self_organizing/simulation.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "core/input_error.h"
#include "trees/random.h"
#include "trees/self_organizing/bending.h"
#include "trees/self_organizing/competition.h"
#include "trees/self_organizing/growth.h"
#include "trees/self_organizing/markers.h"
#include "trees/self_organizing/pipe_model.h"
#include "trees/self_organizing/shadow_grid.h"
#include "trees/self_organizing/vigour.h"

namespace landsim::trees::self_organizing {
namespace {

class Simulation {
 public:
  Simulation(const Parameters& p, std::uint64_t seed)
      : base_(p),
        p_(p),
        plant_(p.internode_length),
        shadows_(p.light, p.light.voxel * p.internode_length),
        marker_rng_(seed, 1),
        growth_rng_(seed, 2) {
    shadows_.cast(plant_[0].tip, +1.0);
    add_envelope_markers(p.envelope, marker_rng_, markers_);
  }

  // One step; false when nothing grew and no markers can still come.
  bool step(int s) {
    follow_phase(s);
    prune(s);
    const std::vector<BudRef> buds = plant_.buds();
    std::vector<Vec3> positions(buds.size()), directions(buds.size());
    for (std::size_t b = 0; b < buds.size(); ++b)
      positions[b] = plant_[buds[b].internode].tip, directions[b] = plant_.bud_direction(buds[b]);
    add_markers(s, positions, directions);
    select_branch(buds);
    const std::vector<BudSpace> space = compete(buds, positions, directions);
    set_bud_light(buds, directions);
    gather_light(plant_);
    distribute_vigour(plant_, p_.vigour.alpha, p_.vigour.apical_control);
    shed(s);
    const int grown = grow_shoots(buds, space, s);
    // A phase still to begin may let growth resume (a region elsewhere, other rules).
    return grown > 0 || more_markers_after(s) ||
           (!base_.phases.empty() && base_.phases.back().from_step > s);
  }

  Plant& plant() { return plant_; }
  const MarkerSet& markers() const { return markers_; }
  std::size_t shed_branches = 0, shed_internodes = 0;

 private:
  void prune(int s) {
    for (const Pruning& cut : p_.prunings) {
      if (cut.step != s) continue;
      const std::uint32_t at = nearest_internode(plant_, cut.at);
      if (at == kNone || at == 0)
        throw InputError((cut.where.empty() ? "prune" : cut.where) + ": no branch to cut at step " +
                         std::to_string(s) + " (the tree is its seedling internode)");
      std::vector<std::uint32_t> gone;
      if (cut.stub) {
        assign_widths(plant_, p_.width);  // the width the stub keeps
        gone = plant_.cut_above(at, plant_[at].width, s);
      } else {
        gone = plant_.prune(at, s);
      }
      for (std::uint32_t k : gone) shadows_.cast(plant_[k].tip, -1.0);
    }
  }

  // Every bud, selected or not, consumes the markers in its occupancy zone; the buds of the
  // selected branch (all buds outside selective growth) share the markers left; the others get
  // none.
  std::vector<BudSpace> compete(const std::vector<BudRef>& buds, const std::vector<Vec3>& positions,
                                const std::vector<Vec3>& directions) {
    const double l = p_.internode_length;
    std::vector<std::uint8_t> competing;  // empty: every bud competes
    if (phase_ != nullptr && phase_->selective)
      for (const BudRef& b : buds) competing.push_back(selected(b) ? 1 : 0);
    return claim_markers(markers_, {positions, directions, competing}, p_.space.occupancy * l,
                         (p_.space.occupancy + p_.space.perception) * l, p_.space.perception_angle);
  }

  // TreeSketch's selective mode: when a selective phase begins, the bud nearest its point
  // is selected (ties to the earlier bud); then the branch is that bud's shoot and all that
  // grows from it, marked per internode each step (a parent precedes its children).
  void select_branch(const std::vector<BudRef>& buds) {
    if (phase_ == nullptr || !phase_->selective) return;
    if (selecting_ != phase_) {
      selecting_ = phase_;
      branch_root_ = kNone;
      selected_bud_ = {kNone, false};
      double nearest = std::numeric_limits<double>::infinity();
      for (const BudRef& b : buds) {
        const double d = length(plant_[b.internode].tip - phase_->select);
        if (d < nearest) nearest = d, selected_bud_ = b;
      }
    }
    in_branch_.assign(plant_.size(), false);
    for (std::uint32_t i = branch_root_; i < plant_.size(); ++i)
      in_branch_[i] =
          i == branch_root_ || (plant_[i].parent != kNone && in_branch_[plant_[i].parent]);
  }

  bool selected(const BudRef& b) const {
    if (phase_ == nullptr || !phase_->selective) return true;
    if (branch_root_ == kNone)
      return b.internode == selected_bud_.internode && b.lateral == selected_bud_.lateral;
    return b.internode < in_branch_.size() && in_branch_[b.internode];
  }

  // This step's markers; autonomous ones in the cones of the buds at `positions`.
  void add_markers(int s, const std::vector<Vec3>& positions, const std::vector<Vec3>& directions) {
    markers_.expire(s);
    for (const Lasso& lasso : p_.lassos)
      if (lasso.outline().start_step == s) add_lasso_markers(lasso, marker_rng_, markers_);
    for (const BrushStroke& stroke : p_.strokes)
      add_stroke_markers(stroke, s, marker_rng_, markers_);
    if (p_.space.autonomous_markers > 0) {
      // Refused before the buds drop them: a step's autonomous markers are known in advance.
      const std::size_t coming =
          positions.size() * static_cast<std::size_t>(p_.space.autonomous_markers);
      if (coming > p_.max_autonomous_markers) refuse_autonomous(s, coming, positions.size());
      if (markers_.size() + coming > p_.max_markers) refuse_markers(s, markers_.size() + coming);
      const double radius = (p_.space.occupancy + p_.space.perception) * p_.internode_length;
      for (std::size_t b = 0; b < positions.size(); ++b)
        add_cone_markers(positions[b], directions[b], p_.space.perception_angle, radius,
                         p_.space.autonomous_markers, s, marker_rng_, markers_);
    }
    if (markers_.size() > p_.max_markers) refuse_markers(s, markers_.size());
  }

  [[noreturn]] void refuse_autonomous(int s, std::size_t coming, std::size_t buds) const {
    throw InputError(where() + "self-organising growth would drop " + std::to_string(coming) +
                     " autonomous markers at step " + std::to_string(s) + " (" +
                     std::to_string(buds) + " buds), more than the limit of " +
                     std::to_string(p_.max_autonomous_markers) +
                     " a step: lower space.autonomous_markers or vigour.max_shoot");
  }

  [[noreturn]] void refuse_markers(int s, std::size_t held) const {
    throw InputError(where() + "self-organising growth would hold more than the limit of " +
                     std::to_string(p_.max_markers) + " markers at step " + std::to_string(s) +
                     " (" + std::to_string(held) + "): lower " + marker_keys());
  }

  // Q = b * L^kappa for every bud: light feeds the resource; space only decides which buds
  // can use theirs (docs/SELF_ORGANIZING.md).
  // Each bud on its own (on every core: a bud writes only its own field of its internode).
  void set_bud_light(const std::vector<BudRef>& buds, const std::vector<Vec3>& directions) {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, buds.size(), 2048),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t b = r.begin(); b != r.end(); ++b)
                          set_light(buds[b], directions[b]);
                      });
  }

  void set_light(const BudRef& bud, const Vec3& direction) {
    Internode& n = plant_[bud.internode];
    // Gravimorphism is the lateral buds' (TreeSketch: "lateral buds depending on their
    // orientation on horizontal or slanted parent axes"); a terminal bud continues its axis.
    const double b_grav =
        bud.lateral ? gravimorphism(p_.gravimorphism, n.direction, direction) : 1.0;
    const double q = b_grav * std::pow(shadows_.exposure(n.tip), p_.light.sensitivity);
    (bud.lateral ? n.lateral_light : n.terminal_light) = q;
  }

  void shed(int s) {
    if (!(p_.vigour.shedding > 0.0)) return;
    const std::vector<std::uint32_t> branches = branches_to_shed(plant_, p_.vigour.shedding);
    if (branches.empty()) return;
    assign_widths(plant_, p_.width);  // the kept widths of the shed branches
    for (std::uint32_t root : branches) {
      const auto gone = plant_.shed(root, plant_[root].width, s);
      for (std::uint32_t k : gone) shadows_.cast(plant_[k].tip, -1.0);
      ++shed_branches;
      shed_internodes += gone.size();
    }
  }

  int grow_shoots(const std::vector<BudRef>& buds, const std::vector<BudSpace>& space, int s) {
    // Only buds with space grow: n = floor(v / v_max * n_max) among them.
    double v_max = 0.0;
    for (std::size_t b = 0; b < buds.size(); ++b)
      if (space[b].markers > 0 && selected(buds[b])) v_max = std::max(v_max, vigour_of(buds[b]));
    if (!(v_max > 0.0)) return 0;
    std::vector<int> metamers(buds.size(), 0);
    std::size_t allotted = 0;
    for (std::size_t b = 0; b < buds.size(); ++b) {
      const Internode& n = plant_[buds[b].internode];
      if (space[b].markers == 0 || !n.alive ||
          (buds[b].lateral ? !n.lateral_bud : !n.terminal_bud) || !selected(buds[b]))
        continue;
      metamers[b] = static_cast<int>(std::floor(vigour_of(buds[b]) / v_max * p_.vigour.max_shoot));
      allotted += static_cast<std::size_t>(std::max(metamers[b], 0));
    }
    // Refused before the step grows what it has allotted, not after: an exploding tree's
    // last step is most of its growth (time and memory; docs/RELIABILITY.md).
    if (plant_.size() + allotted > p_.max_internodes)
      refuse_internodes(s, plant_.size() + allotted);
    int grown = 0;
    for (std::size_t b = 0; b < buds.size(); ++b) {
      if (metamers[b] <= 0) continue;
      const std::size_t first = plant_.size();
      const int added = grow_shoot(plant_, p_, buds[b], metamers[b], space[b].direction, s,
                                   growth_rng_, shadows_);
      grown += added;
      if (added > 0 && selecting_ == phase_ && phase_ != nullptr && phase_->selective &&
          branch_root_ == kNone)
        branch_root_ = static_cast<std::uint32_t>(first);  // the selected bud's shoot
      for (std::size_t k = first; k < plant_.size(); ++k)
        plant_[static_cast<std::uint32_t>(k)].shoot_vigour = vigour_of(buds[b]);
    }
    return grown;
  }

  [[noreturn]] void refuse_internodes(int s, std::size_t allotted) const {
    throw InputError(where() + "self-organising growth would exceed the limit of " +
                     std::to_string(p_.max_internodes) + " internodes at step " +
                     std::to_string(s) + " (its shoots would make " + std::to_string(allotted) +
                     "): lower growth.steps, vigour.max_shoot or " + marker_keys());
  }

  std::string where() const { return base_.source.empty() ? "" : base_.source + ": "; }

  // The keys of this species that supply markers: what feeds an exploding growth.
  std::string marker_keys() const {
    std::vector<std::string> keys;
    if (!base_.strokes.empty()) keys.push_back("the strokes' markers_per_step and max_age");
    if (base_.envelope.kind != EnvelopeKind::none) keys.push_back("envelope.density");
    if (!base_.lassos.empty()) keys.push_back("the lassos' density");
    if (base_.space.autonomous_markers > 0) keys.push_back("space.autonomous_markers");
    std::string out;
    for (std::size_t k = 0; k < keys.size(); ++k)
      out += (k == 0 ? "" : k + 1 == keys.size() ? " or " : ", ") + keys[k];
    return out.empty() ? "the markers" : out;
  }

  double vigour_of(const BudRef& bud) const {
    const Internode& n = plant_[bud.internode];
    return n.alive ? (bud.lateral ? n.lateral_vigour : n.terminal_vigour) : 0.0;
  }

  bool more_markers_after(int s) const {
    for (const Lasso& lasso : p_.lassos)
      if (lasso.outline().start_step > s) return true;
    if (p_.space.autonomous_markers > 0) return false;  // nothing grew with them: nothing will
    for (const BrushStroke& stroke : p_.strokes) {
      StrokePoint where;
      if (brush_position(stroke, s + 1, where) || s + 1 < stroke.start_step) return true;
    }
    return false;
  }

  // The rules in effect at step s: the last phase begun by then, or the species' own.
  void follow_phase(int s) {
    phase_ = nullptr;
    for (const GrowthPhase& ph : base_.phases)
      if (ph.from_step <= s) phase_ = &ph;
    p_.vigour = phase_ != nullptr ? phase_->vigour : base_.vigour;
    p_.gravimorphism = phase_ != nullptr ? phase_->gravimorphism : base_.gravimorphism;
    p_.direction = phase_ != nullptr ? phase_->direction : base_.direction;
  }

  const Parameters& base_;
  Parameters p_;  // the species' parameters with the current phase's rules
  const GrowthPhase* phase_ = nullptr;
  const GrowthPhase* selecting_ = nullptr;  // the selective phase whose bud is chosen
  BudRef selected_bud_{kNone, false};
  std::uint32_t branch_root_ = kNone;  // the selected bud's first internode, once grown
  std::vector<bool> in_branch_;        // per internode: in the selected branch
  Plant plant_;
  ShadowGrid shadows_;
  MarkerSet markers_;
  Random marker_rng_;
  Random growth_rng_;
};

}  // namespace

Plant grow(const Parameters& p, std::uint64_t seed, GrowthStatistics* statistics) {
  Simulation sim(p, seed);
  int steps = 0;
  while (steps < p.steps)
    if (!sim.step(++steps)) break;
  assign_widths(sim.plant(), p.width);
  if (statistics != nullptr) {
    statistics->steps = steps;
    statistics->internodes = sim.plant().living();
    statistics->shed_branches = sim.shed_branches;
    statistics->shed_internodes = sim.shed_internodes;
    statistics->markers_left = sim.markers().size();
    statistics->buds = sim.plant().buds().size();
  }
  return std::move(sim.plant());
}

}  // namespace landsim::trees::self_organizing
