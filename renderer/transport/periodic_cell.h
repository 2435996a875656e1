#pragma once
// Rays through a periodic cell (RAMI's cyclic boundary; renderer::PeriodicCell): the scene
// repeats without end in x and y, so a ray is traced leg by leg inside the one drawn cell,
// each leg ending where it leaves through a side and the next starting on the opposite side.
// The geometry is never copied for it (only what crosses a side, by the scene builder).
#include <optional>

#include "renderer/acceleration/embree_scene.h"
#include "renderer/camera.h"
#include "renderer/scene.h"

namespace landsim::renderer {

// A ray that would meet nothing in ever so many cells (grazing the canopy's layer) has gone.
inline constexpr int kMaxPeriodicLegs = 4096;

// `ray` moved by whole periods so that its origin lies in the cell (the same ray, by
// periodicity).
Ray wrap_into(const PeriodicCell& cell, Ray ray);

// The distance along `ray` (origin in the cell) to where it leaves through a side; infinity
// for a vertical ray.
float side_exit(const PeriodicCell& cell, const Ray& ray);

// The first hit of `ray` in the endless repetition, found leg by leg; `ray` becomes the leg
// that hit (its origin in the cell), so the hit's distance is along it, and `travelled` (when
// given) the distance along the original ray to that leg's origin (0 without a hit): what a
// medium, which varies only with height, is traversed over. A ray coming down from above the
// cell starts its first leg at the cell's top.
std::optional<Hit> periodic_intersect(const EmbreeScene& embree, const PeriodicCell& cell, Ray& ray,
                                      std::uint32_t mask, double* travelled = nullptr);
bool periodic_occluded(const EmbreeScene& embree, const PeriodicCell& cell, Ray ray,
                       std::uint32_t mask);

}  // namespace landsim::renderer
