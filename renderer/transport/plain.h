#pragma once
// The plain beyond the drawn ground: a horizontal surface at the height of the ground's rim,
// everywhere outside the ground's footprint, so that a ray leaving the terrain downward (past
// its edge, or through a nodata hole) meets ground at a finite distance, shaded, shadowed and
// hazed like the terrain (docs/ATMOSPHERE.md "The plain beyond the grid"). It is not in
// Embree: a ray that meets nothing there asks plain_hit.
//
// As a solid it is everything outside the footprint at or below the rim's height; inside the
// footprint it closes the nodata holes as a lid at that height. A ray from below that height
// inside the footprint (a valley at the edge) meets it where it leaves the footprint: the
// plain's vertical skirt, which hides the low sky as the land beyond would.
#include <optional>

#include "core/vec3.h"
#include "renderer/camera.h"
#include "renderer/scene.h"

namespace landsim::renderer {

struct PlainSurface {
  bool present = false;  // false: no ground or Ground::plain off (rays below see the sky's)
  float height = 0.0f;   // scene frame z
  // The drawn ground's footprint in x and y, scene frame.
  float min_x = 0.0f, min_y = 0.0f, max_x = 0.0f, max_y = 0.0f;
};

// The plain of `ground`: its height is ground.plain_height when set (the scene builder's
// mean along the grid's edge), else the mean height of the mesh's vertices on the rim of its
// footprint.
PlainSurface plain_surface(const Ground& ground);

struct PlainHit {
  float t = 0.0f;
  Vec3f normal;  // up on the plain and its lids, toward the footprint on its skirt
};

// Where a ray that met no geometry meets the plain; empty: it leaves into the sky.
std::optional<PlainHit> plain_hit(const PlainSurface& plain, const Ray& ray);

}  // namespace landsim::renderer
