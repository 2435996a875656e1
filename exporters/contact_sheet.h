#pragma once
// Contact sheets of trees (Hoetzlein 2022's Figure 6): each tree rendered alone in its own
// tile, on flat ground under sun and sky, framed to its bounds, the tiles laid out in rows.
// `landsim discover` fills one with trees sampled from the harmonic core's parameter space.
#include <filesystem>
#include <string>
#include <vector>

#include "renderer/output/film.h"
#include "renderer/scene.h"
#include "trees/degradation.h"
#include "trees/geometry.h"

namespace landsim::exporters {

struct ContactSheetOptions {
  int columns = 6;
  int tile = 256;  // pixels, square
  int spp = 8;
  std::uint64_t seed = 1;
  // Per tile (optional): draw its tree at the range degradation of this calibrated range
  // (Weber & Penn section 5), however closely the tile frames it; with `factors`.
  std::vector<double> detail_r2;
  trees::DegradationFactors factors;
};

// One tile per tree, row by row. Deterministic for the same trees and options.
renderer::Film render_contact_sheet(const std::vector<trees::TreeGeometry>& trees,
                                    const ContactSheetOptions& options);

// A Weber & Penn Plate 4: one tree at each range (metres, the paper's calibration: r2 =
// range), every panel framed alike, in one row.
renderer::Film render_plate(const trees::TreeGeometry& tree, const std::vector<double>& ranges,
                            ContactSheetOptions options);

// The sheet as a preview PNG (renderer::write_preview_png) with a label at the top left of
// each tile.
void write_labelled_png(const renderer::Film& sheet, const std::vector<std::string>& labels,
                        const ContactSheetOptions& options, const std::filesystem::path& path);

// A studio for single trees: flat ground `half` metres each way from the origin, sun from
// the south-west, physical sky. A cutaway keeps only the ground north of the origin (y >= 0),
// so what lies below the ground south of it (a root system) shows, as in a cross-section.
renderer::Scene studio_scene(float half, bool cutaway = false);

// A person-sized reference figure, 1.75 m tall, standing at the origin (for scale), as a
// prototype dressed in red.
renderer::TreePrototype person_figure();

}  // namespace landsim::exporters
