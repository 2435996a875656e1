#include "scenes/builder/detail/plain_albedo.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "renderer/spectra/spectral_colour.h"

namespace landsim::scenes::detail {
namespace {

// A cell at the edge of the ground: valid, with a 4-neighbour outside the grid or nodata.
bool edge_cell(const terrain::ElevationGrid& g, int c, int r) {
  if (c < 0 || r < 0 || c >= g.cols() || r >= g.rows() || !g.valid(c, r)) return false;
  const auto open = [&](int cc, int rr) {
    return cc < 0 || rr < 0 || cc >= g.cols() || rr >= g.rows() || !g.valid(cc, rr);
  };
  return open(c - 1, r) || open(c + 1, r) || open(c, r - 1) || open(c, r + 1);
}

}  // namespace

EdgeGround edge_ground(const renderer::Ground& ground, const terrain::ElevationGrid& grid,
                       const Vec3& origin) {
  const terrain::GeoTransform& t = grid.transform();
  const terrain::GroundMesh& mesh = ground.mesh;
  EdgeGround edge;
  Vec3 sum{};
  for (std::size_t k = 0; k < mesh.triangle_count(); ++k) {
    const Vec3f a = mesh.vertices[mesh.indices[3 * k]], b = mesh.vertices[mesh.indices[3 * k + 1]],
                c = mesh.vertices[mesh.indices[3 * k + 2]];
    const Vec3 centre = Vec3((a + b + c) / 3.0f) + origin;
    const auto col = static_cast<int>(std::floor((centre.x - t.origin_x) / t.cell_size_x));
    const auto row = static_cast<int>(std::floor((t.origin_y - centre.y) / t.cell_size_y));
    const std::uint8_t id = ground.material_id(k);
    if (!edge_cell(grid, col, row) || id == renderer::Ground::kSurroundings) continue;
    sum += Vec3(ground.material(id).albedo);
    edge.materials.push_back(id);
  }
  const std::size_t n = edge.materials.size();
  edge.albedo = n == 0 ? ground.albedo : Vec3f(sum / static_cast<double>(n));
  std::array<std::size_t, renderer::kGroundMaterials> count{};
  for (const std::uint8_t id : edge.materials) ++count[id];
  edge.commonest =
      static_cast<std::uint8_t>(std::max_element(count.begin(), count.end()) - count.begin());
  return edge;
}

std::shared_ptr<const renderer::SpectralOptics> edge_optics(const renderer::Ground& ground,
                                                            const EdgeGround& edge) {
  const auto spectrum = [&](std::uint8_t id) {
    const auto& o = ground.optics[id];
    return o ? o->reflectance : renderer::reflectance_spectrum(ground.material(id).albedo);
  };
  renderer::Spectrum sum;
  for (const std::uint8_t id : edge.materials) sum += spectrum(id);
  const std::size_t n = edge.materials.size();
  auto out = std::make_shared<renderer::SpectralOptics>();
  out->reflectance = n == 0 ? spectrum(0) : sum * (1.0f / static_cast<float>(n));
  return out;
}

std::optional<float> edge_height(const terrain::ElevationGrid& grid, const Vec3& origin) {
  double sum = 0.0;
  std::size_t n = 0;
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c)
      if (edge_cell(grid, c, r)) {
        sum += grid.at(c, r);
        ++n;
      }
  if (n == 0) return std::nullopt;
  return static_cast<float>(sum / static_cast<double>(n) - origin.z);
}

}  // namespace landsim::scenes::detail
