// The `landsim` Python module (docs/PYTHON.md): scenarios, renders in memory and to image
// sets, trees and the memory estimate, all through the libraries `landsim` itself calls.
#include <pybind11/pybind11.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <dlfcn.h>

#include <filesystem>

#include "core/input_warnings.h"
#include "core/module_loader.h"
#include "python/bindings/image_binding.h"
#include "python/bindings/render_binding.h"
#include "python/bindings/scenario_binding.h"
#include "python/bindings/tree_binding.h"

namespace py = pybind11;

namespace {

// Logs to stderr as the program's, quieter by default: a script's own output comes first.
void log_to_stderr() {
  auto logger = spdlog::get("landsim");
  if (!logger) logger = spdlog::stderr_color_mt("landsim");
  logger->set_pattern("landsim: %^%l%$: %v");
  logger->set_level(spdlog::level::warn);
  spdlog::set_default_logger(logger);
  landsim::input_warnings().sink = [](const std::string& m) { spdlog::warn("{}", m); };
}

}  // namespace

PYBIND11_MODULE(_landsim, m) {
  m.doc() = "landsim: ray-traced landscape renderer for scene simulation";
  m.attr("__version__") = LANDSIM_VERSION;
  // The run-time modules (rasters, images, meshes) sit beside this extension.
  // (__file__ is set only after this function returns: the loader says where this is.)
  Dl_info self{};
  if (dladdr(reinterpret_cast<void*>(&log_to_stderr), &self) != 0 && self.dli_fname != nullptr)
    landsim::embedded_module_directory() = std::filesystem::path(self.dli_fname).parent_path();
  log_to_stderr();
  m.def(
      "set_log_level",
      [](const std::string& level) {
        const spdlog::level::level_enum l = spdlog::level::from_str(level);
        if (l == spdlog::level::off && level != "off")
          throw py::value_error("log level '" + level +
                                "': expected trace, debug, info, warning, error or off");
        spdlog::set_level(l);
      },
      py::arg("level"), "Log level of landsim's messages on stderr (default: warning).");
  m.def(
      "set_strict", [](bool strict) { landsim::input_warnings().strict = strict; },
      py::arg("strict"), "Refuse input that would only be warned about (as --strict).");
  landsim::python::bind_scenario(m);
  landsim::python::bind_image(m);
  landsim::python::bind_render(m);
  landsim::python::bind_tree(m);
}
