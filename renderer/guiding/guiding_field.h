#pragma once
// Practical path guiding's spatio-directional field (Müller, Gross and Novák 2017, section 3):
// a binary tree over space whose leaves each hold a directional tree
// (renderer/guiding/directional_tree.h) learned from the paths that scattered there. The
// paper grows one tree record by record; landsim keeps each training pass's records and
// builds both trees from them at once (a region is split at its longest axis's middle while
// it holds more than kRecordsPerRegion), so that the field depends only on the records and
// their order, never on the threads that traced them: the same scene gives the same field
// and the same image on any thread count (docs/PERFORMANCE.md "Guided paths").
#include <cstdint>
#include <vector>

#include "core/vec3.h"
#include "renderer/guiding/directional_tree.h"

namespace landsim::renderer {

// What a path learned at one of its surface vertices: where it was, the direction it left
// in, and the flux that came back along it (the incident radiance over the direction's
// density).
struct GuideRecord {
  Vec3f position;
  Vec3f direction;
  float flux = 0.0f;
};

class GuidingField {
 public:
  // A region is split while it holds more records than this: enough for its directional
  // tree to resolve a few dozen quadrants (the paper's c = 12,000 for a pass of one sample a
  // pixel; landsim's passes are a fraction of that).
  static constexpr std::size_t kRecordsPerRegion = 4000;
  // A region with fewer records learns nothing: its paths sample the BSDF alone.
  static constexpr std::size_t kLeastRecords = 64;

  GuidingField() = default;
  // Built from one training pass's records (reordered).
  explicit GuidingField(std::vector<GuideRecord> records);

  // The directional tree of the region holding `p` (a point outside the records' box takes
  // the nearest region); null where nothing was learned.
  const DirectionalTree* at(const Vec3f& p) const;
  std::size_t region_count() const;
  std::size_t directional_nodes() const;

 private:
  struct Node {
    float split = 0.0f;
    int axis = -1;             // -1: a leaf
    std::uint32_t child[2]{};  // below and above the split
    std::int32_t tree = -1;    // the leaf's directional tree, -1: none
  };
  std::uint32_t build(std::vector<GuideRecord>& records, std::size_t first, std::size_t last,
                      Vec3f lo, Vec3f hi, int depth);
  std::vector<Node> nodes_;
  std::vector<DirectionalTree> trees_;
};

}  // namespace landsim::renderer
