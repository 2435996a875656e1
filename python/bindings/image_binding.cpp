#include "python/bindings/image_binding.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include <nlohmann/json.hpp>

#include <cstdlib>

#include <string>
#include <vector>

#include "core/input_error.h"
#include "renderer/output/image_output.h"

namespace py = pybind11;

namespace landsim::python {
namespace {

using scenes::RenderedImage;

const renderer::Film& film_of(const py::object& self) { return self.cast<RenderedImage&>().film; }

// A read-only view of one channel of `data` (every `stride` values per pixel, from `offset`),
// kept alive by the image `self`; `channels` > 1 gives (height, width, channels).
template <class T>
py::array plane(const py::object& self, const std::vector<T>& data, int stride, int offset,
                int channels = 1) {
  const renderer::Film& f = film_of(self);
  const auto w = static_cast<py::ssize_t>(f.width()), h = static_cast<py::ssize_t>(f.height());
  const auto item = static_cast<py::ssize_t>(sizeof(T)), s = static_cast<py::ssize_t>(stride);
  std::vector<py::ssize_t> shape{h, w}, strides{item * s * w, item * s};
  if (channels > 1) {
    shape.push_back(channels);
    strides.push_back(item);
  }
  py::array a(py::dtype::of<T>(), shape, strides, data.data() + offset, self);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

// Luminance as the EXR's Y channel holds it (Film::luminance, pixel by pixel).
py::array luminance(const renderer::Film& f) {
  py::array_t<float> y({f.height(), f.width()});
  auto out = y.mutable_unchecked<2>();
  for (int r = 0; r < f.height(); ++r)
    for (int c = 0; c < f.width(); ++c) out(r, c) = f.luminance(c, r);
  return y;
}

py::dict bands(const py::object& self) {
  const renderer::Film& f = film_of(self);
  py::dict out;
  for (int b = 0; b < f.band_count(); ++b)
    out[py::str(renderer::band_layer(f.band_name(b)))] = plane(self, f.band_data(b), 1, 0);
  return out;
}

// Every channel by its EXR name.
py::dict layers(const py::object& self) {
  const renderer::Film& f = film_of(self);
  py::dict out;
  const char* rgb[] = {"R", "G", "B"};
  const char* xyz[] = {"X", "Y", "Z"};
  for (int c = 0; c < 3; ++c) {
    out[rgb[c]] = plane(self, f.rgb_data(), 3, c);
    out[py::str(std::string("N.") + xyz[c])] = plane(self, f.normal_data(), 3, c);
    out[py::str(std::string("albedo.") + rgb[c])] = plane(self, f.albedo_data(), 3, c);
    out[py::str(std::string("P.") + xyz[c])] = plane(self, f.position_data(), 3, c);
  }
  out["Y"] = luminance(f);
  out["Z"] = plane(self, f.depth_data(), 1, 0);
  out["object"] = plane(self, f.object_data(), 1, 0);
  out["species"] = plane(self, f.species_data(), 1, 0);
  out["instance"] = plane(self, f.instance_data(), 1, 0);
  out["lod"] = plane(self, f.level_data(), 1, 0);
  out["target"] = plane(self, f.target_data(), 1, 0);
  out["coverage"] = plane(self, f.coverage_data(), 1, 0);
  out["Y.variance"] = plane(self, f.variance_data(), 1, 0);
  out["spp"] = plane(self, f.samples_data(), 1, 0);
  for (auto [name, array] : bands(self)) out[name] = array;
  return out;
}

py::object json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

std::string attribute(const renderer::ImageMetadata& meta, const std::string& key) {
  for (const auto& [k, v] : meta)
    if (k == key) return v;
  return {};
}

// An EXR landsim wrote, as the image `render` would have returned; `entry` is its manifest
// entry (JSON) when the set's manifest lists it.
renderer::Film read_film(const std::filesystem::path& path, renderer::ImageMetadata& meta) {
  try {
    return renderer::read_exr(path, &meta);
  } catch (const InputError&) {
    throw;
  } catch (const std::exception& e) {
    const std::string what = e.what();
    throw InputError(what.find(path.string()) == std::string::npos ? path.string() + ": " + what
                                                                   : what);
  }
}

scenes::RenderedImage read_image(const std::filesystem::path& path, std::string entry = "{}") {
  renderer::ImageMetadata meta;
  renderer::Film film = read_film(path, meta);
  scenes::RenderedImage image{{}, std::move(film), std::move(meta), std::move(entry)};
  scenes::ImageReport& r = image.report;
  r.exr = path;
  r.view = attribute(image.metadata, "view");
  r.width = image.film.width();
  r.height = image.film.height();
  const auto number = [&](const char* key) {
    const std::string v = attribute(image.metadata, key);
    return v.empty() ? 0.0 : std::strtod(v.c_str(), nullptr);
  };
  r.time_s = number("time_s");
  r.spp = static_cast<int>(number("spp"));
  r.exposure_ev100 = number("exposure_ev100");
  return image;
}

// Every image the manifest of the set in `dir` lists, with its entry.
std::vector<scenes::RenderedImage> read_image_set(const std::filesystem::path& dir) {
  const nlohmann::json manifest = scenes::read_manifest(dir);
  std::vector<scenes::RenderedImage> images;
  for (const nlohmann::json& entry : manifest["images"]) {
    if (!entry.is_object() || !entry.contains("path") || !entry["path"].is_string())
      throw InputError((dir / "manifest.json").string() +
                       ": an image entry without a \"path\" (expected a landsim manifest)");
    scenes::RenderedImage image = read_image(dir / entry["path"].get<std::string>(), entry.dump());
    image.report.frame_index = entry.value("frame_index", std::size_t{0});
    images.push_back(std::move(image));
  }
  return images;
}

}  // namespace

void bind_image(py::module_& m) {
  py::class_<RenderedImage>(m, "Image", R"(One rendered image: layers as numpy arrays.

layers holds every channel by the name the EXR gives it (R, G, B, Y, Z, N.X, albedo.R,
object, species, instance, lod, target, coverage, P.X, Y.variance, spp, band.<name>, ...);
rgb, depth, normal, ... are the same planes shaped for use. manifest is the image's entry
in manifest.json; metadata the EXR's landsim/ attributes.)")
      .def_property_readonly("width", [](const RenderedImage& i) { return i.film.width(); })
      .def_property_readonly("height", [](const RenderedImage& i) { return i.film.height(); })
      .def_property_readonly("view", [](const RenderedImage& i) { return i.report.view; })
      .def_property_readonly("frame_index",
                             [](const RenderedImage& i) { return i.report.frame_index; })
      .def_property_readonly("time_s", [](const RenderedImage& i) { return i.report.time_s; })
      .def_property_readonly("spp", [](const RenderedImage& i) { return i.report.spp; })
      .def_property_readonly("exposure_ev100",
                             [](const RenderedImage& i) { return i.report.exposure_ev100; })
      .def_property_readonly("layers", &layers, "Every channel by its EXR name")
      .def_property_readonly("bands", &bands,
                             "Band, photon and reflectance layers (band.*, photons.*, ...)")
      .def_property_readonly(
          "rgb", [](const py::object& s) { return plane(s, film_of(s).rgb_data(), 3, 0, 3); },
          "Radiance, scene-linear Rec. 709, (height, width, 3); Y = 0.2126 R + 0.7152 G + "
          "0.0722 B is luminance in cd/m2")
      .def_property_readonly(
          "luminance", [](const py::object& s) { return luminance(film_of(s)); },
          "Luminance, cd/m2 (the EXR's Y)")
      .def_property_readonly(
          "depth", [](const py::object& s) { return plane(s, film_of(s).depth_data(), 1, 0); },
          "Distance from the camera, m (inf: sky)")
      .def_property_readonly(
          "normal", [](const py::object& s) { return plane(s, film_of(s).normal_data(), 3, 0, 3); })
      .def_property_readonly(
          "albedo", [](const py::object& s) { return plane(s, film_of(s).albedo_data(), 3, 0, 3); })
      .def_property_readonly(
          "position",
          [](const py::object& s) { return plane(s, film_of(s).position_data(), 3, 0, 3); },
          "First hit, scene frame (add metadata scene_origin for the terrain's CRS)")
      .def_property_readonly(
          "object", [](const py::object& s) { return plane(s, film_of(s).object_data(), 1, 0); },
          "Object class per pixel (manifest legend)")
      .def_property_readonly(
          "species", [](const py::object& s) { return plane(s, film_of(s).species_data(), 1, 0); })
      .def_property_readonly(
          "instance",
          [](const py::object& s) { return plane(s, film_of(s).instance_data(), 1, 0); })
      .def_property_readonly(
          "variance",
          [](const py::object& s) { return plane(s, film_of(s).variance_data(), 1, 0); },
          "Variance of the pixel's luminance estimate, (cd/m2)^2")
      .def_property_readonly("manifest",
                             [](const RenderedImage& i) { return json(i.manifest_entry); })
      .def_property_readonly("metadata",
                             [](const RenderedImage& i) {
                               py::dict d;
                               for (const auto& [k, v] : i.metadata) d[py::str(k)] = v;
                               return d;
                             })
      .def_property_readonly("stats",
                             [](const RenderedImage& i) {
                               const renderer::RenderStats& s = i.report.stats;
                               py::dict d;
                               d["seconds"] = s.seconds;
                               d["setup_seconds"] = s.setup_seconds;
                               d["rays"] = s.rays;
                               d["rays_per_second"] = s.rays_per_second();
                               return d;
                             })
      .def(
          "save",
          [](const RenderedImage& i, const std::filesystem::path& path) {
            renderer::write_exr(i.film, path, i.metadata);
          },
          py::arg("path"),
          "Writes the image as an EXR with every layer and attribute (landsim.read_image reads "
          "it back).")
      .def("__repr__", [](const RenderedImage& i) {
        return "<landsim.Image " + i.report.view + " frame " +
               std::to_string(i.report.frame_index) + ", " + std::to_string(i.film.width()) +
               " x " + std::to_string(i.film.height()) + ">";
      });
  m.def(
      "read_image", [](const std::filesystem::path& path) { return read_image(path); },
      py::arg("path"),
      "An EXR landsim wrote (landsim render, render_set, Image.save) as a landsim.Image; "
      "ScenarioError for a file that is not one.");
  m.def("read_image_set", &read_image_set, py::arg("dir"),
        "Every image of an image set (its manifest.json), each with its manifest entry.");
}

}  // namespace landsim::python
