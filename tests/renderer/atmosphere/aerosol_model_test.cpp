// RAMI4ATM's aerosol models by wavelength (docs/ATMOSPHERE.md "Aerosol models"): the values
// at the dataset's own wavelengths are the published ones (taken here from the NetCDF files
// of Govaerts 2021, not from landsim's CSV), and between them linear in wavelength.
#include "renderer/atmosphere/aerosol_model.h"

#include <gtest/gtest.h>

#include <stdexcept>

namespace landsim::renderer {
namespace {

TEST(AerosolModel, GivesTheDatasetsValuesAtItsWavelengths) {
  const auto continental = AerosolModel::named("rami4atm-continental");
  EXPECT_NEAR(continental->single_scattering_albedo(550.0), 0.97331806, 1e-7);
  EXPECT_NEAR(continental->single_scattering_albedo(670.0), 0.96780870, 1e-7);
  EXPECT_NEAR(continental->relative_extinction(550.0), 1.0, 1e-12);
  EXPECT_NEAR(continental->relative_extinction(670.0), 0.015979502 / 0.02300406, 1e-7);
  // Asymmetry: the dataset's first moment over its zeroth (7.7917 / 12.5982 at 550 nm,
  // 7.3602 / 12.6040 at 670 nm, by trapezoids in the cosine as the table interpolates).
  EXPECT_NEAR(continental->phase(550.0).asymmetry(), 0.61848, 2e-3);
  EXPECT_NEAR(continental->phase(670.0).asymmetry(), 0.58396, 2e-3);
  const auto desert = AerosolModel::named("rami4atm-desert");
  EXPECT_NEAR(desert->single_scattering_albedo(550.0), 0.93139418, 1e-7);
  EXPECT_NEAR(desert->relative_extinction(860.0), 0.025125728 / 0.031535548, 1e-7);
  EXPECT_NEAR(desert->phase(550.0).asymmetry(), 8.7433 / 12.6027, 2e-3);
}

TEST(AerosolModel, IsLinearInWavelengthBetweenItsWavelengths) {
  const auto m = AerosolModel::named("rami4atm-continental");
  // Midway between 633 and 670 nm: the mean of the two.
  EXPECT_NEAR(m->single_scattering_albedo(651.5), 0.5 * (0.97026699 + 0.96780870), 1e-7);
  EXPECT_NEAR(m->relative_extinction(651.5), 0.5 * (0.017711361 + 0.015979502) / 0.02300406, 1e-7);
  // The phase function's backscatter too (0.36607 and 0.39520 sr^-1 in the dataset's
  // normalisation, 4 pi over the sphere; the table's is 1).
  const double back = m->phase(651.5).eval(-1.0f) * 4.0 * 3.14159265358979;
  EXPECT_NEAR(back, 0.5 * (0.36607 + 0.39520), 0.004);
  // Beyond its last wavelength kept (1240 nm) and before its first (350 nm): the ends'.
  EXPECT_EQ(m->single_scattering_albedo(300.0), m->single_scattering_albedo(350.0));
  EXPECT_THROW(AerosolModel::named("maritime"), std::invalid_argument);
  for (const std::string& name : AerosolModel::names())
    EXPECT_EQ(AerosolModel::named(name)->name(), name);
}

}  // namespace
}  // namespace landsim::renderer
