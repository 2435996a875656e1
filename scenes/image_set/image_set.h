#pragma once
// An image set: every frame of every view of a scenario path-traced into a directory of
// EXR images with PNG previews and a manifest.json (docs/SCENARIO.md "Image sets"), with the
// memory budget checked before anything is built, resume from finished images and
// checkpoints, the scene rebuilt between frames only when the wind moves it, and object
// truth. The one entry point `landsim render`, its MPI driver and scripts call; the CLI
// only parses its options and prints.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json_fwd.hpp>

#include "renderer/output/image_output.h"
#include "renderer/transport/render.h"
#include "scenes/scenario/scenario.h"

namespace landsim::scenes {

// One image this process wrote.
struct ImageReport {
  std::filesystem::path exr;
  std::string view;
  std::size_t frame_index = 0;
  double time_s = 0.0;
  int width = 0, height = 0, spp = 0;
  double exposure_ev100 = 0.0;
  renderer::RenderStats stats;
  bool shared = false;                 // rendered with other processes (SharedRender)
  double communication_seconds = 0.0;  // shared: time in messages
};

// Images rendered by several processes at once (MPI): every process calls
// render_image_set with the same scenario, and `render` renders a view together with the
// others, filling the report's stats; only the `writer` gets the film (the others an
// empty one) and writes files.
struct SharedRender {
  bool writer = true;
  std::function<renderer::Film(const renderer::Renderer&, const renderer::View&,
                               const renderer::RenderOptions&, ImageReport&)>
      render;
};

// An image kept in memory (ImageSetOptions::keep): what its EXR would hold and its manifest
// entry.
struct RenderedImage {
  ImageReport report;
  renderer::Film film;               // with its derived layers (reflectance)
  renderer::ImageMetadata metadata;  // the EXR's "landsim/<key>" attributes
  std::string manifest_entry;        // JSON
};

struct ImageSetOptions {
  std::filesystem::path out_dir = "out";
  // false: nothing is written (no EXR, preview, rasters, sensor image, checkpoint or
  // manifest) and each image goes to `keep` instead (the Python module's render). A sensor's
  // digital numbers are then not made: its photon layers are in the film.
  bool write_files = true;
  std::function<void(RenderedImage&&)> keep;
  // Called with an image's name and the fraction of it done, from one thread at a time.
  std::function<void(const std::string& image, double fraction)> progress;
  // Keep finished images of this very scenario in out_dir and continue from checkpoints.
  bool resume = false;
  // Render only this image of the set (frame-major: frame x views + view); no manifest.
  std::optional<std::size_t> task_index;
  // The memory budget in bytes; else [render] max_memory, else a share of this machine's
  // memory divided among `ranks_on_node` processes.
  std::optional<std::uint64_t> max_memory;
  std::string max_memory_source = "--max-memory";  // how a refusal names max_memory
  int ranks_on_node = 1;
  const SharedRender* shared = nullptr;  // nullptr: this process renders alone
  // Asked between waves of tiles (true stops the render, its checkpoint written) and before
  // each scene is built (true stops before building it).
  std::function<bool()> stop;
  // Called on the writing process after each image is written.
  std::function<void(const ImageReport&)> written;
};

struct ImageSetResult {
  std::vector<ImageReport> images;                    // written by this process
  std::size_t skipped = 0;                            // finished images kept (resume)
  double scene_seconds = 0.0;                         // building scenes
  std::uint64_t memory_estimate_bytes = 0;            // the largest of
  std::vector<std::uint64_t> memory_estimates_bytes;  // each scene's estimate, in order
  // Set when `stop` stopped the render: the image it stopped at; its checkpoint holds the
  // progress unless the stop came before its scene was built (`stopped_before_tracing`).
  std::optional<std::string> stopped_at;
  bool stopped_before_tracing = false;
};

// Renders the set into options.out_dir. Throws InputError for bad input (nothing written);
// when a later image fails, the manifest lists the finished ones with "complete": false.
ImageSetResult render_image_set(const Scenario& scenario, const ImageSetOptions& options);

// Checks that every image of the set is in out_dir; writes the manifest when none is
// missing. Returns the missing files.
std::vector<std::string> check_image_set(const Scenario& scenario,
                                         const std::filesystem::path& out_dir);

// The manifest.json of the image set in `dir`, as the tools that read a set take it (compare,
// annotate, sense): an object with an "images" array. Throws InputError naming the file.
nlohmann::json read_manifest(const std::filesystem::path& dir);

}  // namespace landsim::scenes
