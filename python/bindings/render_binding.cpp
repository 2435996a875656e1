#include "python/bindings/render_binding.h"

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <nlohmann/json.hpp>

#include <optional>

#include "python/bindings/cancellable_call.h"
#include "python/bindings/scenario_binding.h"
#include "scenes/builder/memory_estimate.h"
#include "scenes/image_set/image_set.h"
#include "scenes/scenario/render_choices.h"

namespace py = pybind11;

namespace landsim::python {
namespace {

// The scenario with the call's choices applied, as `landsim render`'s options apply them.
scenes::Scenario chosen(const PyScenario& s, const scenes::RenderChoices& c) {
  scenes::Scenario out = s.scenario();
  scenes::apply_render_choices(out, c);
  return out;
}

py::object json(const nlohmann::json& j) {
  return py::module_::import("json").attr("loads")(j.dump());
}

std::optional<std::uint64_t> memory_budget(std::optional<double> max_memory) {
  if (!max_memory) return std::nullopt;
  if (*max_memory <= 0.0) throw py::value_error("max_memory: expected a number of bytes > 0");
  return static_cast<std::uint64_t>(*max_memory);
}

// The view `view` names, or the first: render() renders one view as `--view` does.
std::string view_name(const PyScenario& s, const std::optional<std::string>& view) {
  scenes::require_views(s.scenario());
  return view ? *view : s.scenario().views.front().name;
}

scenes::RenderedImage render(const PyScenario& s, const std::optional<std::string>& view,
                             std::size_t frame, std::optional<int> spp, std::optional<int> width,
                             std::optional<int> height, std::optional<int> threads,
                             std::optional<double> max_memory, const py::object& progress) {
  const scenes::Scenario scenario =
      chosen(s, {spp, threads, width, height, view_name(s, view), "render(view=...)"});
  if (frame >= scenario.render.frames.size())
    throw py::index_error("frame " + std::to_string(frame) + ": the scenario has " +
                          std::to_string(scenario.render.frames.size()) + " frames");
  std::optional<scenes::RenderedImage> image;
  bool stopped = false;
  call_cancellable(
      [&](CallState& state) {
        scenes::ImageSetOptions o;
        o.write_files = false;
        o.task_index = frame;  // one view: image `frame` of the set
        o.max_memory = memory_budget(max_memory);
        o.max_memory_source = "max_memory";
        o.keep = [&](scenes::RenderedImage&& i) { image.emplace(std::move(i)); };
        o.progress = [&](const std::string& name, double f) { state.report(name, f); };
        o.stop = [&] { return state.cancelled(); };
        stopped = scenes::render_image_set(scenario, o).stopped_at.has_value();
      },
      progress);
  if (stopped || !image) throw std::runtime_error("the render stopped before its image was made");
  return std::move(*image);
}

py::dict render_set(const PyScenario& s, const std::filesystem::path& out_dir,
                    const std::optional<std::string>& view, std::optional<int> spp,
                    std::optional<int> width, std::optional<int> height, std::optional<int> threads,
                    bool resume, std::optional<double> max_memory, const py::object& progress) {
  const scenes::Scenario scenario =
      chosen(s, {spp, threads, width, height, view.value_or(""), "render_set(view=...)"});
  scenes::ImageSetResult result;
  call_cancellable(
      [&](CallState& state) {
        scenes::ImageSetOptions o;
        o.out_dir = out_dir;
        o.resume = resume;
        o.max_memory = memory_budget(max_memory);
        o.max_memory_source = "max_memory";
        o.progress = [&](const std::string& name, double f) { state.report(name, f); };
        o.stop = [&] { return state.cancelled(); };
        result = scenes::render_image_set(scenario, o);
      },
      progress);
  py::list images;
  for (const scenes::ImageReport& r : result.images) {
    py::dict d;
    d["exr"] = r.exr.string();
    d["view"] = r.view;
    d["frame_index"] = r.frame_index;
    d["time_s"] = r.time_s;
    d["width"] = r.width;
    d["height"] = r.height;
    d["spp"] = r.spp;
    d["exposure_ev100"] = r.exposure_ev100;
    d["seconds"] = r.stats.seconds;
    d["rays"] = r.stats.rays;
    images.append(d);
  }
  py::dict out;
  out["images"] = images;
  out["skipped"] = result.skipped;
  out["scene_seconds"] = result.scene_seconds;
  out["memory_estimate_bytes"] = result.memory_estimate_bytes;
  out["manifest"] = (out_dir / "manifest.json").string();
  return out;
}

}  // namespace

void bind_render(py::module_& m) {
  m.def("render", &render, py::arg("scenario"), py::arg("view") = py::none(), py::arg("frame") = 0,
        py::arg("spp") = py::none(), py::arg("width") = py::none(), py::arg("height") = py::none(),
        py::arg("threads") = py::none(), py::arg("max_memory") = py::none(),
        py::arg("progress") = py::none(),
        R"(Renders one image in memory and returns a landsim.Image.

The view (default: the first) is rendered as `landsim render --view NAME` renders it, frame
`frame` of the scenario's frames; spp, width, height and threads as the command's options.
progress(image, fraction) is called now and then; Ctrl-C stops the render and raises
KeyboardInterrupt. Nothing is written to disk.)");
  m.def("render_set", &render_set, py::arg("scenario"), py::arg("out_dir"),
        py::arg("view") = py::none(), py::arg("spp") = py::none(), py::arg("width") = py::none(),
        py::arg("height") = py::none(), py::arg("threads") = py::none(), py::arg("resume") = false,
        py::arg("max_memory") = py::none(), py::arg("progress") = py::none(),
        R"(Renders the image set into out_dir exactly as `landsim render` does (EXR, PNG,
rasters, sensor images, manifest.json) and returns what was written. Ctrl-C stops at the next
wave of tiles with the checkpoint written (resume=True continues) and raises
KeyboardInterrupt.)");
  m.def(
      "info",
      [](const PyScenario& s) {
        return json(scenes::estimate_json(s.scenario(), scenes::estimate_memory(s.scenario())));
      },
      py::arg("scenario"),
      "The scene's expected trees, triangles and memory, as `landsim info --json` gives them.");
}

}  // namespace landsim::python
