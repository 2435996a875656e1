#include "scenes/scenario/detail/atmosphere_reader.h"

#include "params/table_reader.h"
#include "scenes/scenario/detail/haze_reader.h"
#include "scenes/scenario/detail/toml_tables.h"

namespace landsim::scenes::detail {

namespace {

using params::Range;
using params::TableReader;

// The aerosol layer: how much (visibility or optical depth at 550 nm), where (exponential from
// the lowest ground, or uniform between two heights above it) and of what type.
void read_aerosol(TableReader& r, renderer::Haze& h) {
  if (r.has("visibility") == r.has("optical_depth"))
    r.fail("visibility", "give either visibility (metres) or optical_depth (at 550 nm)");
  if (r.has("visibility"))
    h.visibility = r.number("visibility", Range{10.0, 1e7});
  else
    h.aerosol_optical_depth = r.number("optical_depth", Range{0.0, 100.0});
  const std::string profile = r.choice("profile", {"exponential", "uniform"}, "exponential");
  if (profile == "uniform") {
    h.aerosol_profile = renderer::AerosolProfile::uniform;
    if (r.has("scale_height")) r.fail("scale_height", "only with profile = \"exponential\"");
    h.uniform_bottom = r.number("bottom", Range{0.0, 1e5}, h.uniform_bottom);
    h.uniform_top = r.number("top", Range{0.0, 1e5}, h.uniform_top);
    if (!(h.uniform_top > h.uniform_bottom)) r.fail("top", "expected top above bottom");
  } else {
    for (const char* k : {"bottom", "top"})
      if (r.has(k)) r.fail(k, "only with profile = \"uniform\"");
    h.scale_height = r.number("scale_height", Range{10.0, 1e5}, h.scale_height);
  }
  // The optical type (docs/ATMOSPHERE.md "Aerosol models"): OPAC's continental average,
  // shaped by the optics keys, unless a dataset by wavelength is named (the names
  // renderer::AerosolModel knows).
  const std::string type =
      r.choice("type", {"continental-average", "rami4atm-continental", "rami4atm-desert"},
               "continental-average");
  if (type != "continental-average") {
    for (const char* k : {"angstrom", "colour", "single_scattering_albedo", "phase", "asymmetry",
                          "phase_angles", "phase_values", "phase_moments"})
      if (r.has(k))
        r.fail(k, "type = \"" + type +
                      "\" gives the extinction, albedo and phase function "
                      "by wavelength: remove " +
                      k + " (or use type = \"continental-average\")");
    h.aerosol_model = type;
    r.finish();
    return;
  }
  h.angstrom = r.number("angstrom", Range{-1.0, 4.0}, h.angstrom);
  read_aerosol_optics(r, h);
  r.finish();
}

// What Hosek-Wilkie's sky carried of its own, refused beside the one atmosphere.
void refuse_second_descriptions(const toml::table& root, const std::string& file,
                                const Scenario& s) {
  if (root.contains("haze")) {
    TableReader r(root, "", file);
    r.fail_at(*root.get("haze"), "[haze]",
              "it describes the aerosol a second time beside [atmosphere]: give it as "
              "[atmosphere.aerosol] (visibility or optical_depth, scale_height, asymmetry, ...)");
  }
  if (const toml::table* sky = root["sky"].as_table()) {
    TableReader r(*sky, "sky", file);
    if (sky->contains("turbidity"))
      r.fail("turbidity",
             "turbidity is the Hosek-Wilkie sky's own aerosol: with [atmosphere], give the "
             "aerosol as [atmosphere.aerosol] visibility or optical_depth");
    if (sky->contains("model") && s.sky.model != renderer::SkyKind::atmosphere)
      r.fail("model",
             "with [atmosphere] the sky is the atmosphere's (model = \"atmosphere\"); the "
             "Hosek-Wilkie and other models carry an atmosphere of their own: remove "
             "[atmosphere] to use them");
  }
  if (s.sun.irradiance) {
    TableReader r(sub_table(root, "sun", file, true), "sun", file);
    r.fail("irradiance",
           "with [atmosphere] the sun is Thuillier's spectrum above the atmosphere, dimmed by "
           "the air it crosses: remove irradiance");
  }
}

// Hosek-Wilkie's and Preetham's skies carry an aerosol of their own (their turbidity), in the
// sun's beam as in the sky: a [haze] aerosol beside them would count the aerosol twice
// (docs/ATMOSPHERE.md "One atmosphere"). A plane-parallel [haze] layer under a sky of no
// atmosphere of its own (none, gradient) is the radiative-transfer checks' medium.
void refuse_an_aerosol_beside_a_sky_of_its_own(const toml::table& root, const std::string& file,
                                               const Scenario& s) {
  const bool own =
      s.sky.model == renderer::SkyKind::hosek_wilkie || s.sky.model == renderer::SkyKind::preetham;
  if (!own || !root.contains("haze")) return;
  TableReader r(root, "", file);
  r.fail_at(*root.get("haze"), "[haze]",
            std::string("the ") +
                (s.sky.model == renderer::SkyKind::preetham ? "Preetham" : "Hosek-Wilkie") +
                " sky (the default without [atmosphere]) carries an aerosol of its own (its "
                "turbidity), and [haze] would add the aerosol a second time: describe the "
                "atmosphere once as [atmosphere] and [atmosphere.aerosol] (visibility or "
                "optical_depth, scale_height, asymmetry, ...), or remove [haze] to keep the "
                "sky as a look-development sky");
}

}  // namespace

void read_atmosphere(const toml::table& root, const std::string& file, Scenario& s) {
  const bool table = root.contains("atmosphere");
  if (!table && s.sky.model != renderer::SkyKind::atmosphere) {
    refuse_an_aerosol_beside_a_sky_of_its_own(root, file, s);
    return;
  }
  refuse_second_descriptions(root, file, s);
  s.sky.model = renderer::SkyKind::atmosphere;
  renderer::Haze h;
  h.enabled = true;
  h.aerosol = false;
  renderer::MolecularColumn column;
  if (table) {
    TableReader r(sub_table(root, "atmosphere", file, true), "atmosphere", file);
    r.choice("profile", {"us-standard"}, "us-standard");
    column.scattering = r.boolean("rayleigh", column.scattering);
    column.absorption = r.boolean("ozone", column.absorption);
    if (const auto du = r.optional_number("ozone_column", Range{0.0, 1000.0})) {
      if (!column.absorption) r.fail("ozone_column", "only with ozone = true");
      column.ozone_column = *du;
    }
    // Every scattering event traced by default (exact); or a haze point's light but the sun's
    // beam looked up in a table traced once over the plain (docs/ATMOSPHERE.md "One
    // atmosphere": its error measured on a valley).
    const std::string light = r.choice("multiple_scattering", {"paths", "table"}, "paths");
    h.scattering =
        light == "table" ? renderer::HazeScattering::table : renderer::HazeScattering::paths;
    if (r.has("aerosol")) {
      TableReader a = r.table("aerosol");
      h.aerosol = true;
      read_aerosol(a, h);
    }
    r.finish();
  }
  h.column = column;
  s.haze = h;
}

}  // namespace landsim::scenes::detail
