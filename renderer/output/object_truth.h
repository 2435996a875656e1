#pragma once
// Truth about the scene objects in a rendered image, for detection studies: how much of each
// object is seen, how much would be without occluders, where, how far, and how it stands out
// from what surrounds it (docs/OBJECTS.md "Truth").
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "renderer/output/film.h"
#include "renderer/scene.h"

namespace landsim::renderer {

// Pixel bounds, inclusive: x0, y0, x1, y1 (row 0 at the top).
using PixelBox = std::array<int, 4>;

// Sub-pixel truth: every sample of a pixel counts. A pixel "covers" an object when any of its
// samples first hits it (coverage > 0; the film's target layer names the object most of
// them hit, its coverage layer the share); coverage sums are in pixels.
// An object's oriented box: its mesh's bounds in its own frame (x right, y front, z up)
// placed in the scene frame; the angles are Tait-Bryan: heading clockwise from north, then
// pitch (front up positive), then roll (right side down positive).
struct ObjectBox {
  Vec3 centre;  // scene frame
  Vec3 size;    // metres along right, front, up
  Vec3 right, front, up;
  double heading_deg = 0.0, pitch_deg = 0.0, roll_deg = 0.0;
  Vec3 centre_camera;  // camera frame, OpenCV's: x right, y down, z forward
  // The box's axes (right, front, up) as the columns, in the camera frame, row-major.
  std::array<double, 9> rotation_camera{};
};

struct ObjectTruth {
  std::string name;
  std::string mesh;  // its mesh file (its class is the file's stem)
  // Pixels whose target is this object, and the sum of their coverage.
  std::uint64_t visible_pixels = 0;
  double visible_coverage = 0.0;
  // The same for the samples' rays in a scene of the objects alone: the projected
  // footprint, occluders ignored.
  std::uint64_t footprint_pixels = 0;
  double footprint_coverage = 0.0;
  // visible / footprint coverage; 0 with an empty footprint.
  double visible_fraction = 0.0;
  std::optional<PixelBox> bbox;  // of the visible pixels; empty when none is
  std::optional<PixelBox> footprint_bbox;
  // The footprint's pixels (any sample) as COCO's uncompressed RLE: column-major runs, the
  // first of zeros; the amodal mask of the annotations.
  std::vector<std::uint32_t> footprint_rle;
  double range = 0.0;  // metres, camera to the centre of the object's bounding box
  ObjectBox box;
  // The share of the footprint beyond the frame (the same rays continued past its edges);
  // empty where that is not measured (fisheye and spherical views, a huge part beyond).
  std::optional<double> truncation;
  // Contrast of the visible pixels against their surround: mean luminance (cd/m2) of the
  // visible pixels, of the background ring (pixels within `ring_width` of a visible pixel
  // that no object covers), and Weber's contrast (L - Lb) / Lb (empty when Lb is 0 or the
  // object unseen).
  double luminance = 0.0;
  double background_luminance = 0.0;
  std::uint64_t background_pixels = 0;
  int ring_width = 0;
  std::optional<double> contrast;
};

// The ring's width in pixels for an object whose visible pixels span `box`: a tenth of its
// larger side, at least 3 pixels.
int ring_width(const PixelBox& box);

// Every object's truth in `film`, rendered from `view` with the scene's seed; `centre_first`
// as the render's option (the first sample through the pixel centre).
std::vector<ObjectTruth> object_truth(const Scene& scene, const View& view, const Film& film,
                                      bool centre_first);

}  // namespace landsim::renderer
