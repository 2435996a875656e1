#pragma once
// The training passes of guided paths (Müller, Gross and Novák 2017, section 5: each pass
// twice the samples of the one before, each learning from paths guided by the last). landsim
// spends RenderSettings::guiding_training of the render's samples on three passes (1 : 2 : 4
// of them); a pass's budget's fraction of a sample goes to an evenly spread subset of pixels.
// Records are gathered per row of tiles and joined in row order, so the field, and the image,
// are the same on any thread count. The passes' images are not kept: the render that follows
// is guided by a field fixed before it, and stays unbiased.
#include <cstdint>
#include <memory>

#include "renderer/camera.h"
#include "renderer/guiding/guiding_field.h"
#include "renderer/scene.h"

namespace landsim::renderer {

class PathTracer;

struct GuideTrainingStats {
  std::uint64_t paths = 0, records = 0, rays = 0;
  std::size_t regions = 0, directional_nodes = 0;  // of the last pass's field
  double seconds = 0.0;
};

// Trains a field for `view` on `threads` threads (0: every core) and leaves `tracer` guided
// by it.
std::shared_ptr<const GuidingField> train_guiding(PathTracer& tracer, const Camera& camera,
                                                  const View& view, const RenderSettings& settings,
                                                  int threads, GuideTrainingStats* stats = nullptr);

// The passes' budgets in samples a pixel: `share` of `spp`, split 1 : 2 : 4.
inline constexpr int kGuideTrainingPasses = 3;
double guide_pass_budget(double share, int spp, int pass);

}  // namespace landsim::renderer
