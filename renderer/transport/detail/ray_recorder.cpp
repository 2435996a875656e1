#include "renderer/transport/detail/ray_recorder.h"

#include "renderer/acceleration/embree_scene.h"

namespace landsim::renderer::detail {

RayRecorder::RayRecorder(const EmbreeScene& scene, std::size_t workers)
    : scene_(scene), lists_(workers) {
  scene_.recorder_ = &lists_;
}

RayRecorder::~RayRecorder() { scene_.recorder_ = nullptr; }

std::vector<RecordedRay> RayRecorder::rays() const {
  std::vector<RecordedRay> all;
  for (const auto& list : lists_) all.insert(all.end(), list.begin(), list.end());
  return all;
}

}  // namespace landsim::renderer::detail
