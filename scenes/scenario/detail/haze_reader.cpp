#include "scenes/scenario/detail/haze_reader.h"

#include <algorithm>

#include "params/table_reader.h"
#include "scenes/scenario/detail/toml_tables.h"

namespace landsim::scenes::detail {

namespace {

using params::Range;
using params::TableReader;

// [haze]'s phase function: Henyey-Greenstein by default, or isotropic, Rayleigh, a table by
// scattering angle, or Legendre moments.
void read_phase(TableReader& r, renderer::Haze& h) {
  const std::string phase =
      r.choice("phase", {"henyey-greenstein", "isotropic", "rayleigh", "table", "legendre"},
               "henyey-greenstein");
  h.asymmetry = r.number("asymmetry", Range{-0.95, 0.95}, h.asymmetry);
  // Bounded: a table is evaluated by bisection, a Legendre series summed at 4001 cosines.
  h.phase_angles = number_list(r, "phase_angles", 2, 100000, Range{0.0, 180.0});
  h.phase_values = number_list(r, "phase_values", 2, 100000, Range{0.0, 1e12});
  h.phase_moments = number_list(r, "phase_moments", 1, 1000, Range{-1.0, 1.0});
  if (phase == "table") {
    h.phase = renderer::AerosolPhase::table;
    if (h.phase_angles.empty() || h.phase_angles.size() != h.phase_values.size())
      r.fail("phase_angles", "phase = \"table\" needs phase_angles and as many phase_values");
    for (std::size_t i = 1; i < h.phase_angles.size(); ++i)
      if (!(h.phase_angles[i] > h.phase_angles[i - 1]))
        r.fail("phase_angles", "expected increasing angles");
    if (h.phase_angles.front() != 0.0 || h.phase_angles.back() != 180.0)
      r.fail("phase_angles", "expected angles from 0 to 180 degrees");
    // Normalised over the sphere, the table must hold some light: all zeros scatter nothing.
    if (std::none_of(h.phase_values.begin(), h.phase_values.end(),
                     [](double v) { return v > 0.0; }))
      r.fail("phase_values",
             "expected a positive value at some angle (all zeros scatter no light)");
  } else if (phase == "legendre") {
    h.phase = renderer::AerosolPhase::legendre;
    if (h.phase_moments.empty() || h.phase_moments.front() != 1.0)
      r.fail("phase_moments", "phase = \"legendre\" needs phase_moments starting with 1");
  } else {
    h.phase = phase == "isotropic"  ? renderer::AerosolPhase::isotropic
              : phase == "rayleigh" ? renderer::AerosolPhase::rayleigh
                                    : renderer::AerosolPhase::henyey_greenstein;
  }
}

}  // namespace

void read_aerosol_optics(TableReader& r, renderer::Haze& h) {
  if (r.has("colour") && r.has("single_scattering_albedo"))
    r.fail("single_scattering_albedo", "give either colour or single_scattering_albedo");
  h.albedo = to_vec3f(r.vec3("colour", kUnit, Vec3(h.albedo)));
  if (const auto a = r.optional_number("single_scattering_albedo", Range{0.0, 1.0}))
    h.albedo = Vec3f{static_cast<float>(*a), static_cast<float>(*a), static_cast<float>(*a)};
  read_phase(r, h);
}

renderer::Haze read_haze(const toml::table& root, const std::string& file) {
  renderer::Haze h;
  if (!root.contains("haze")) return h;
  TableReader r(sub_table(root, "haze", file, true), "haze", file);
  h.enabled = true;
  if (r.has("layer")) {
    // The plane-parallel layer of the radiative-transfer checks (docs/ATMOSPHERE.md).
    TableReader layer = r.table("layer");
    renderer::HazeLayer l;
    l.optical_depth = layer.number("optical_depth", Range{1e-6, 1e3});
    l.top = layer.number("top", Range{1e-3, 1e6}, l.top);
    layer.finish();
    h.layer = l;
    h.molecular = false;
  } else {
    h.visibility = r.number("visibility", Range{10.0, 1e7});
    h.scale_height = r.number("scale_height", Range{10.0, 1e5}, h.scale_height);
    h.angstrom = r.number("angstrom", Range{-1.0, 4.0}, h.angstrom);
    h.molecular = r.boolean("molecular", h.molecular);
  }
  // The haze's light other than the sun's single scattering: tabulated by default, traced
  // with `paths` (the plane-parallel layer of the checks: traced unless told).
  const std::string light =
      r.choice("multiple_scattering", {"table", "paths"}, h.layer ? "paths" : "table");
  h.scattering =
      light == "paths" ? renderer::HazeScattering::paths : renderer::HazeScattering::table;
  read_aerosol_optics(r, h);
  r.finish();
  return h;
}

}  // namespace landsim::scenes::detail
