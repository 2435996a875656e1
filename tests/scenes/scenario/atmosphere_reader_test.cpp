// [atmosphere] (docs/ATMOSPHERE.md "One atmosphere", docs/SCENARIO.md): read into the medium
// and the sky, and every second description of the same atmosphere refused with the key to
// use instead.
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "scenes/scenario/scenario.h"
#include "tests/support/input_error_of.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::TempDir;

std::string base(const std::string& sun_extra = "") {
  return "[terrain]\nelevation = \"" +
         landsim::testing::source_file("data/terrain/volcano.asc").string() +
         "\"\n[sun]\nelevation = 30.0\nazimuth = 200\n" + sun_extra +
         "\n[[views]]\nname = \"a\"\nposition = [0.0, 0.0, 300.0]\n"
         "target = [300.0, 400.0, 150.0]\n";
}

Scenario load(const std::string& text) {
  TempDir dir;
  return load_scenario(dir.write("scene.toml", text));
}

std::string error_of(const std::string& text) {
  return landsim::testing::input_error_of([&] { load(text); });
}

TEST(AtmosphereReader, ReadsTheMoleculesAndTheAerosolLayer) {
  const Scenario s = load(base() +
                          "[atmosphere]\nozone_column = 300\n"
                          "[atmosphere.aerosol]\noptical_depth = 0.2\nprofile = \"uniform\"\n"
                          "top = 2000\nsingle_scattering_albedo = 0.9\nasymmetry = 0.6\n");
  EXPECT_EQ(s.sky.model, renderer::SkyKind::atmosphere);
  ASSERT_TRUE(s.haze.enabled);
  ASSERT_TRUE(s.haze.column.has_value());
  EXPECT_TRUE(s.haze.column->scattering);
  EXPECT_TRUE(s.haze.column->absorption);
  EXPECT_EQ(s.haze.column->ozone_column, 300.0);
  EXPECT_TRUE(s.haze.aerosol);
  EXPECT_EQ(s.haze.aerosol_optical_depth, 0.2);
  EXPECT_EQ(s.haze.aerosol_profile, renderer::AerosolProfile::uniform);
  EXPECT_EQ(s.haze.uniform_top, 2000.0);
  EXPECT_EQ(s.haze.asymmetry, 0.6);
  EXPECT_EQ(s.haze.scattering, renderer::HazeScattering::paths);
  // Molecules alone: no aerosol table, no aerosol; the model by name alone is the same.
  const Scenario clear = load(base() + "[atmosphere]\nozone = false\n");
  EXPECT_FALSE(clear.haze.aerosol);
  EXPECT_FALSE(clear.haze.column->absorption);
  EXPECT_TRUE(load(base() + "[sky]\nmodel = \"atmosphere\"\n").haze.column.has_value());
  EXPECT_EQ(load(base() + "[atmosphere]\nmultiple_scattering = \"table\"\n").haze.scattering,
            renderer::HazeScattering::table);
}

TEST(AtmosphereReader, ReadsANamedAerosolModelAndRefusesTheOpticsItGives) {
  const std::string aerosol = "[atmosphere]\n[atmosphere.aerosol]\noptical_depth = 0.2\n";
  EXPECT_EQ(load(base() + aerosol + "type = \"rami4atm-desert\"\n").haze.aerosol_model,
            "rami4atm-desert");
  EXPECT_EQ(load(base() + aerosol + "type = \"rami4atm-continental\"\n").haze.aerosol_model,
            "rami4atm-continental");
  EXPECT_EQ(load(base() + aerosol).haze.aerosol_model, "");  // OPAC's, shaped by the keys
  // The dataset gives the albedo, the phase function and the wavelength law: a key that
  // would give them again is refused by name.
  for (const char* key : {"asymmetry = 0.6", "single_scattering_albedo = 0.9", "angstrom = 1.2",
                          "phase = \"isotropic\""}) {
    const std::string e =
        error_of(base() + aerosol + "type = \"rami4atm-continental\"\n" + key + "\n");
    EXPECT_NE(e.find(std::string(key).substr(0, std::string(key).find(' '))), std::string::npos)
        << e;
    EXPECT_NE(e.find("by wavelength"), std::string::npos) << e;
  }
  EXPECT_NE(error_of(base() + aerosol + "type = \"maritime\"\n").find("type"), std::string::npos);
}

// A phase table of zeros scatters no light (issue 71): refused at its key, in [haze] as in
// [atmosphere.aerosol], where it used to end in an internal error.
TEST(AtmosphereReader, RefusesAPhaseTableOfZeros) {
  const std::string zeros =
      "phase = \"table\"\nphase_angles = [0.0, 90.0, 180.0]\nphase_values = [0.0, 0.0, 0.0]\n";
  const std::string in_atmosphere =
      error_of(base() + "[atmosphere]\n[atmosphere.aerosol]\noptical_depth = 0.2\n" + zeros);
  EXPECT_NE(in_atmosphere.find("phase_values"), std::string::npos) << in_atmosphere;
  EXPECT_NE(in_atmosphere.find("all zeros scatter no light"), std::string::npos) << in_atmosphere;
  const std::string in_haze = error_of(base() +
                                       "[sky]\nmodel = \"none\"\n[haze]\n"
                                       "layer = { optical_depth = 1.0 }\n" +
                                       zeros);
  EXPECT_NE(in_haze.find("scene.toml:"), std::string::npos) << in_haze;
  EXPECT_NE(in_haze.find("phase_values"), std::string::npos) << in_haze;
}

TEST(AtmosphereReader, RefusesASecondDescriptionNamingTheKeyToUse) {
  const std::string atmosphere = "[atmosphere]\n[atmosphere.aerosol]\nvisibility = 15000\n";
  const std::string haze = error_of(base() + "[haze]\nvisibility = 15000\n" + atmosphere);
  EXPECT_NE(haze.find("[haze]"), std::string::npos) << haze;
  EXPECT_NE(haze.find("[atmosphere.aerosol]"), std::string::npos) << haze;
  const std::string turbidity = error_of(base() + "[sky]\nturbidity = 3\n" + atmosphere);
  EXPECT_NE(turbidity.find("[sky] turbidity"), std::string::npos) << turbidity;
  EXPECT_NE(turbidity.find("visibility or optical_depth"), std::string::npos) << turbidity;
  const std::string model = error_of(base() + "[sky]\nmodel = \"hosek-wilkie\"\n" + atmosphere);
  EXPECT_NE(model.find("[sky] model"), std::string::npos) << model;
  const std::string sun = error_of(base("irradiance = [1e5, 1e5, 1e5]\n") + atmosphere);
  EXPECT_NE(sun.find("[sun] irradiance"), std::string::npos) << sun;
  const std::string both = error_of(
      base() + "[atmosphere]\n[atmosphere.aerosol]\nvisibility = 9000\noptical_depth = 0.3\n");
  EXPECT_NE(both.find("either visibility"), std::string::npos) << both;
  const std::string table = error_of(base() + "[atmosphere]\nmultiple_scattering = \"tables\"\n");
  EXPECT_NE(table.find("[atmosphere] multiple_scattering"), std::string::npos) << table;
  const std::string heights =
      error_of(base() +
               "[atmosphere]\n[atmosphere.aerosol]\noptical_depth = 0.2\nprofile = "
               "\"uniform\"\nbottom = 500\ntop = 400\n");
  EXPECT_NE(heights.find("top"), std::string::npos) << heights;
}

// Hosek-Wilkie's and Preetham's skies hold an aerosol (their turbidity): a [haze] aerosol beside
// either counts it twice, and is refused naming [atmosphere.aerosol]; Hosek-Wilkie alone, and a
// plane-parallel [haze] layer under a sky without an atmosphere of its own, stay.
TEST(AtmosphereReader, RefusesAHazeBesideASkyThatCarriesItsOwnAerosol) {
  for (const std::string sky :
       {"", "[sky]\nmodel = \"hosek-wilkie\"\n", "[sky]\nmodel = \"preetham\"\nturbidity = 3\n"}) {
    const std::string e = error_of(base() + sky + "[haze]\nvisibility = 15000\n");
    EXPECT_NE(e.find("[haze]"), std::string::npos) << sky << e;
    EXPECT_NE(e.find("[atmosphere.aerosol]"), std::string::npos) << e;
    EXPECT_NE(e.find("a second time"), std::string::npos) << e;
  }
  EXPECT_EQ(load(base() + "[sky]\nturbidity = 3\n").sky.model, renderer::SkyKind::hosek_wilkie);
  const Scenario slab = load(base() +
                             "[sky]\nmodel = \"none\"\n[haze]\n[haze.layer]\n"
                             "optical_depth = 0.5\ntop = 1000\n");
  EXPECT_TRUE(slab.haze.layer.has_value());
}

}  // namespace
}  // namespace landsim::scenes
