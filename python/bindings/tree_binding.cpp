#include "python/bindings/tree_binding.h"

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <chrono>

#include "trees/species.h"

namespace py = pybind11;

namespace landsim::python {
namespace {

constexpr const char* kPartNames[trees::kGroupCount] = {"trunk", "level1", "level2", "level3plus",
                                                        "leaves"};

// Every group's triangles in group order, indices running across groups (as the OBJ's).
py::dict mesh(const trees::TreeGeometry& g) {
  std::size_t vertices = 0, faces = 0;
  for (const trees::GroupGeometry& group : g.groups) {
    vertices += group.triangles.vertices.size();
    faces += group.triangles.triangle_count();
  }
  const auto nv = static_cast<py::ssize_t>(vertices), nf = static_cast<py::ssize_t>(faces);
  py::array_t<float> positions({nv, py::ssize_t{3}}), normals({nv, py::ssize_t{3}});
  py::array_t<std::uint32_t> indices({nf, py::ssize_t{3}});
  py::array_t<std::uint8_t> parts(nf);
  auto p = positions.mutable_unchecked<2>(), n = normals.mutable_unchecked<2>();
  auto f = indices.mutable_unchecked<2>();
  auto part = parts.mutable_unchecked<1>();
  py::ssize_t v0 = 0, f0 = 0;
  for (std::size_t k = 0; k < g.groups.size(); ++k) {
    const trees::TriangleSet& t = g.groups[k].triangles;
    for (std::size_t i = 0; i < t.vertices.size(); ++i) {
      const auto row = v0 + static_cast<py::ssize_t>(i);
      p(row, 0) = t.vertices[i].x, p(row, 1) = t.vertices[i].y, p(row, 2) = t.vertices[i].z;
      const Vec3f nn = i < t.normals.size() ? t.normals[i] : Vec3f{};
      n(row, 0) = nn.x, n(row, 1) = nn.y, n(row, 2) = nn.z;
    }
    for (std::size_t i = 0; i < t.triangle_count(); ++i) {
      const auto row = f0 + static_cast<py::ssize_t>(i);
      for (int c = 0; c < 3; ++c)
        f(row, c) = static_cast<std::uint32_t>(v0) + t.indices[3 * i + static_cast<std::size_t>(c)];
      part(row) = static_cast<std::uint8_t>(k);
    }
    v0 += static_cast<py::ssize_t>(t.vertices.size());
    f0 += static_cast<py::ssize_t>(t.triangle_count());
  }
  py::dict out;
  out["vertices"] = positions;
  out["normals"] = normals;
  out["faces"] = indices;
  out["parts"] = parts;
  out["part_names"] = std::vector<std::string>(std::begin(kPartNames), std::end(kPartNames));
  return out;
}

py::dict tree(const std::string& species_file, std::uint64_t seed, std::optional<double> age,
              double quality, double time, double wind, double gust) {
  trees::Species species;
  trees::Tree t;
  double ms = 0.0;
  {
    py::gil_scoped_release release;
    species = trees::load_species(species_file);
    const auto start = std::chrono::steady_clock::now();
    t = trees::generate(species, {seed, time, wind, gust, quality, age.value_or(-1.0)});
    ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  }
  py::dict out = mesh(t.geometry);
  out["species"] = species.name;
  out["core"] = trees::core_name(species);
  out["seed"] = seed;
  py::dict stats;
  stats["stems_per_level"] = t.stats.stems_per_level;
  stats["clones"] = t.stats.clones;
  stats["leaves"] = t.stats.leaves;
  stats["height_m"] = t.stats.height;
  stats["crown_radius_m"] = t.stats.crown_radius;
  stats["generate_ms"] = ms;
  out["stats"] = stats;
  return out;
}

}  // namespace

void bind_tree(py::module_& m) {
  m.def("tree", &tree, py::arg("species"), py::arg("seed") = 1, py::arg("age") = py::none(),
        py::arg("quality") = 1.0, py::arg("time") = 0.0, py::arg("wind") = 0.0,
        py::arg("gust") = 0.0,
        R"(Generates one tree of a species file (as `landsim tree` does) and returns a dict:
vertices (n, 3) float32 and normals, faces (m, 3) uint32, parts (m,) uint8 indexing
part_names (trunk, level1, level2, level3plus, leaves), species, core, seed and stats.
Metres, z up, the base at the origin. age in years (None: the species file's tree).)");
}

}  // namespace landsim::python
