#pragma once
// [objects.place] (docs/OBJECTS.md "Placed by a view"): where an object stands when a
// detection study asks for it by range and bearing from a view, on ground the view sees.
// Candidates are drawn from the seed inside the range band and bearing sector; one is kept
// when enough of the object's sample points are in the frame and seen past the terrain and,
// if asked, the trees (their crowns' bounding cylinders, taken as opaque: the check errs on
// the hidden side). No such place: InputError at the table.
#include <cstdint>
#include <vector>

#include "renderer/acceleration/ground_probe.h"
#include "renderer/scene.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes::detail {

// An object already standing: no other is drawn within reach of it.
struct TakenGround {
  double x = 0.0, y = 0.0;  // scene frame
  double radius = 0.0;      // its footprint's
};

// What the search found, scene frame.
struct Site {
  double x = 0.0, y = 0.0;
  double heading_deg = 0.0;
  double visible = 0.0;  // the share of sample points seen
};

// Draws the place of `o` (which has a siting): the prototype `p` scaled as the object is,
// the scene's views, trees and ground. `seed` mixes [render] seed, the siting's own seed and
// the randomised image; each copy and candidate draws its own numbers.
Site site_object(const ObjectSettings& o, const renderer::ObjectPrototype& p,
                 const renderer::Scene& scene, const renderer::GroundProbe& probe,
                 const std::vector<TakenGround>& taken, std::uint64_t seed);

// The share of the object's sample points (a 3 x 3 x 3 lattice in its bounding box standing
// on the ground at (x, y), turned by `heading_deg`) that `view` sees: in its frame, not
// behind the ground, and (with `trees`) outside every tree's crown cylinder between.
double visible_share(const renderer::ObjectPrototype& p, double scale, double x, double y,
                     double heading_deg, const renderer::View& view, const renderer::Scene& scene,
                     const renderer::GroundProbe& probe, bool trees);

}  // namespace landsim::scenes::detail
