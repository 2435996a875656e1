#pragma once
// The ground's height under a point, read from the very triangles that are rendered (the
// grid's, a context mesh's, the relief's), so that objects stand on the surface the camera
// sees rather than on an interpolation of the grid near it. Built on demand (scene objects)
// and dropped after placement.
#include <memory>
#include <optional>

#include "core/vec3.h"
#include "terrain/ground_mesh.h"

namespace landsim::renderer {

class GroundProbe {
 public:
  explicit GroundProbe(const terrain::GroundMesh& mesh);
  ~GroundProbe();
  GroundProbe(const GroundProbe&) = delete;
  GroundProbe& operator=(const GroundProbe&) = delete;

  // The highest ground surface at (x, y), scene frame; empty off the mesh or over a nodata
  // hole. Safe to call from many threads.
  std::optional<double> height(double x, double y) const;
  // Whether the ground hides `to` from `from` (scene frame): the segment between them meets
  // a ground triangle. Safe to call from many threads.
  bool occluded(const Vec3& from, const Vec3& to) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace landsim::renderer
