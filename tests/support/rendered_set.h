#pragma once
// A scenario's image set rendered in memory, nothing written (ImageSetOptions::keep): the
// images, each with its film, EXR attributes and manifest entry, for a test to look at.
#include <optional>
#include <vector>

#include "scenes/image_set/image_set.h"

namespace landsim::testing {

// Every image of the set, or only image `task_index` (as --task-index renders it).
inline std::vector<scenes::RenderedImage> render_in_memory(
    const scenes::Scenario& s, std::optional<std::size_t> task_index = std::nullopt) {
  std::vector<scenes::RenderedImage> images;
  scenes::ImageSetOptions options;
  options.write_files = false;
  options.task_index = task_index;
  options.keep = [&](scenes::RenderedImage&& image) { images.push_back(std::move(image)); };
  scenes::render_image_set(s, options);
  return images;
}

}  // namespace landsim::testing
