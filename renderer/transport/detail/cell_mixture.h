#pragma once
// Private to renderer/: the directions the haze table's paths leave a height in, and their
// density (renderer/transport/scattering_table.h; docs/ATMOSPHERE.md "Two ways to the haze's
// light"). Path i takes strategy i mod S: each present component's phase function about a
// cell's direction (the cells in turn), the whole sphere (defensive: a forward-peaked phase
// function alone seldom looks back at bright light behind it), and the aerosol's phase
// function about the sun (the light inside a haze peaks there). The density is the balance
// heuristic over every strategy, each weighed by the share of the paths it actually draws:
// N paths over S strategies and 91 cells do not divide evenly (8,192 over 4 and 91: 22 or 23
// a cell), and weighing them as if they did biased the cells by a fraction of a percent.
#include <array>
#include <vector>

#include "core/vec3.h"
#include "renderer/atmosphere/medium.h"

namespace landsim::renderer::detail {

class CellMixture {
 public:
  static constexpr int kCells = 13 * 7;  // ScatteringTable's cosines x azimuths
  using Phases = std::array<std::array<float, kCells>, kMediumComponents>;

  // `paths`: how many paths a height draws (i from 0 to paths - 1).
  CellMixture(const Medium& medium, const std::array<Vec3f, kCells>& directions, const Vec3f& sun,
              int paths);
  const std::vector<int>& present() const { return present_; }

  // Path i's direction from the pair u.
  Vec3f draw(int i, const std::array<float, 2>& u) const;
  // The mixture's density at `next`, and each component's phase function at every cell's
  // direction in `phases` (the cells' weights are phase / density).
  float density(const Vec3f& next, Phases& phases) const;

 private:
  const Medium& medium_;
  const std::array<Vec3f, kCells>& directions_;
  Vec3f sun_;
  std::vector<int> present_;
  int strategies_ = 2;
  // The share of the paths each strategy draws: per component and cell, the sphere's, the
  // aureole's.
  std::array<std::array<float, kCells>, kMediumComponents> cell_share_{};
  float sphere_share_ = 0.0f, aureole_share_ = 0.0f;
};

}  // namespace landsim::renderer::detail
