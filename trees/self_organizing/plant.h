#pragma once
// The growing tree as metamers (Palubicki 2009): each internode ends in a node carrying a
// lateral bud and, until the axis grows on, the terminal bud. The structure is binary: an
// internode's tip leads to its axis's next internode (`main`) and to the first internode of
// the branch its lateral bud grew (`lateral`). Internodes are only appended, so a child's
// index is always above its parent's: reverse index order is basipetal, index order
// acropetal. Shed and pruned parts stay in the array, marked, so indices are stable.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/vec3.h"

namespace landsim::trees::self_organizing {

inline constexpr std::uint32_t kNone = 0xffffffffu;

struct Internode {
  Vec3 base;
  Vec3 tip;
  Vec3 direction;          // unit, base to tip
  Vec3 frame;              // unit, perpendicular to direction: phyllotaxis's reference
  Vec3 lateral_direction;  // unit: where the lateral bud points
  std::uint32_t parent = kNone;
  std::uint32_t main = kNone;
  std::uint32_t lateral = kNone;
  int order = 0;  // branch order: 0 on the trunk
  int rank = 0;   // metamer index along its axis
  int birth = 0;  // the step it grew in
  bool alive = true;
  bool terminal_bud = true;         // alive while main == kNone
  bool lateral_bud = true;          // alive while lateral == kNone
  bool stub = false;                // pruned here: no buds, width frozen
  double frozen_width = 0.0;        // a stub's width, kept
  double shed_lateral_width = 0.0;  // width of a shed lateral branch, kept in the pipe sum

  // Per step: the buds' light (Q) and vigour (v), the internode's totals.
  double terminal_light = 0.0, lateral_light = 0.0;
  double terminal_vigour = 0.0, lateral_vigour = 0.0;
  double light = 0.0;      // Q of everything above the base
  double vigour = 0.0;     // v reaching the base
  std::uint32_t size = 1;  // living internodes in the subtree from here
  double width = 0.0;
  double shoot_vigour = 0.0;  // the vigour of the bud whose shoot this internode is part of
};

// A branch shed or cut at a step, with the width it kept: the plant's history of losses, so
// that the tree of an earlier step can be recovered from the grown one (Plant::at_step).
struct Removal {
  enum class Kind { shed, stub, pruned };
  int step = 0;
  std::uint32_t internode = 0;  // the shed or pruned branch's first internode, or the stub
  double width = 0.0;           // kept in the pipe sum (shed, stub); 0 when pruned
  Kind kind = Kind::shed;
};

// A bud: the node at the internode's tip, terminal or lateral.
struct BudRef {
  std::uint32_t internode;
  bool lateral;
};

class Plant {
 public:
  // The seedling: one vertical internode of length l from the origin.
  explicit Plant(double internode_length);

  const std::vector<Internode>& internodes() const { return internodes_; }
  std::vector<Internode>& internodes() { return internodes_; }
  const Internode& operator[](std::uint32_t i) const { return internodes_[i]; }
  Internode& operator[](std::uint32_t i) { return internodes_[i]; }
  std::size_t size() const { return internodes_.size(); }
  std::size_t living() const { return living_; }

  // Appends an internode grown from `bud` (continuing the axis, or starting a branch).
  std::uint32_t grow(const BudRef& bud, const Vec3& base, const Vec3& tip, const Vec3& frame,
                     const Vec3& lateral_direction, int step);

  // Living buds in a fixed order: by internode, terminal before lateral.
  std::vector<BudRef> buds() const;
  Vec3 bud_direction(const BudRef& bud) const;

  // Every living internode from i up (i included), in index order.
  std::vector<std::uint32_t> subtree(std::uint32_t i) const;
  // Sheds the branch starting at `root` at `step`: its subtree dies, its parent keeps its
  // `width` in the pipe sum. Returns the internodes removed.
  std::vector<std::uint32_t> shed(std::uint32_t root, double width, int step);
  // Removes everything above i and i's buds at `step`; i stays as a stub of width `width`.
  std::vector<std::uint32_t> cut_above(std::uint32_t i, double width, int step);
  // Prunes the branch from i up at `step`: it dies, and its parent keeps none of its width
  // (the tree as if it had never grown); the bud it grew from does not grow again.
  std::vector<std::uint32_t> prune(std::uint32_t i, int step);

  // The plant as it was after growth step `step` (TreeSketch's ungrow, section 3): the
  // internodes born by then (an index prefix: internodes are appended in growth order), with
  // the buds they had, and the sheddings and cuts up to that step replayed. Widths are not
  // set: assign them (pipe_model.h) as after growing.
  Plant at_step(int step) const;
  const std::vector<Removal>& removals() const { return removals_; }

  // True if i is the first internode of a branch (its parent's lateral).
  bool starts_branch(std::uint32_t i) const;

 private:
  // Marks the subtree from i dead; returns the internodes removed.
  std::vector<std::uint32_t> remove(std::uint32_t i);

  std::vector<Internode> internodes_;
  std::size_t living_ = 0;
  std::vector<Removal> removals_;  // in the order they happened
};

}  // namespace landsim::trees::self_organizing
