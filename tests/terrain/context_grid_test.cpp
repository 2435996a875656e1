#include "terrain/context_grid.h"

#include <cpl_conv.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include "core/input_error.h"
#include "core/input_warnings.h"
#include "tests/support/rasters.h"
#include "tests/support/temp_dir.h"

namespace landsim::terrain {
namespace {

using landsim::testing::TempDir;
using landsim::testing::write_raster;

OGRSpatialReferenceH utm_north(int zone) {
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  EXPECT_EQ(OSRImportFromEPSG(srs, 32600 + zone), OGRERR_NONE);
  OSRSetAxisMappingStrategy(srs, OAMS_TRADITIONAL_GIS_ORDER);
  return srs;
}

std::string wkt_of(OGRSpatialReferenceH srs) {
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  std::string out = wkt;
  CPLFree(wkt);
  return out;
}

// The scene's grid in UTM zone 32N near 11.9 degrees east: 50 x 50 cells of 30 m.
constexpr double kWest = 820000.0, kNorth = 665000.0;

ElevationGrid utm32_grid(const std::string& wkt) {
  return ElevationGrid(50, 50, GeoTransform{kWest, kNorth, 30.0, 30.0},
                       std::vector<float>(2500, 100.0f), wkt);
}

TEST(ContextGrid, AContextInAnotherCrsLandsWhereGdalSays) {
  testing::register_gdal();
  TempDir dir;
  OGRSpatialReferenceH zone32 = utm_north(32), zone33 = utm_north(33);
  OGRCoordinateTransformationH to33 = OCTNewCoordinateTransformation(zone32, zone33);
  ASSERT_NE(to33, nullptr);
  // The context in zone 33N around the grid's centre, heights a ramp in its own coordinates:
  // 0.1 m per metre east, 0.05 per metre north, so a misplacement of a cell shows as metres.
  double cx = kWest + 750.0, cy = kNorth - 750.0;
  ASSERT_TRUE(OCTTransform(to33, 1, &cx, &cy, nullptr));
  const int n = 160;
  const double west33 = std::floor(cx) - n * 15.0, north33 = std::floor(cy) + n * 15.0;
  const auto ramp = [&](double x33, double y33) {
    return 1000.0 + 0.1 * (x33 - west33) - 0.05 * (north33 - y33);
  };
  std::vector<double> h;
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c)
      h.push_back(ramp(west33 + (c + 0.5) * 30.0, north33 - (r + 0.5) * 30.0));
  const double gt[6] = {west33, 30.0, 0.0, north33, 0.0, -30.0};
  const std::string path = (dir / "region33.tif").string();
  const std::string wkt33 = wkt_of(zone33);
  write_raster(path, "GTiff", GDT_Float32, n, n, h, gt, wkt33.c_str());

  const ElevationGrid grid = utm32_grid(wkt_of(zone32));
  const ElevationGrid context = load_context(path, grid);
  for (int i = 0; i < 7; ++i)
    for (int j = 0; j < 7; ++j) {
      const double x = kWest - 1000.0 + i * 550.0, y = kNorth + 1000.0 - j * 550.0;
      double x33 = x, y33 = y;
      ASSERT_TRUE(OCTTransform(to33, 1, &x33, &y33, nullptr));
      const std::optional<double> got = context.height(x, y);
      ASSERT_TRUE(got) << x << "," << y;
      EXPECT_NEAR(*got, ramp(x33, y33), 0.5) << x << "," << y;  // 0.5 m: a few metres away
    }
  OCTDestroyCoordinateTransformation(to33);
  OSRDestroySpatialReference(zone32);
  OSRDestroySpatialReference(zone33);
}

TEST(ContextGrid, AContextThatDoesNotOverlapIsRefusedWithBothExtents) {
  testing::register_gdal();
  TempDir dir;
  OGRSpatialReferenceH zone32 = utm_north(32);
  const std::string wkt = wkt_of(zone32);
  const double gt[6] = {100000.0, 30.0, 0.0, 200000.0, 0.0, -30.0};
  const std::string path = (dir / "elsewhere.tif").string();
  write_raster(path, "GTiff", GDT_Float32, 10, 10, std::vector<double>(100, 5.0), gt, wkt.c_str());
  try {
    load_context(path, utm32_grid(wkt));
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(path + ": does not overlap the elevation grid"), std::string::npos) << m;
    EXPECT_NE(m.find("x 100000.0 .. 100300.0"), std::string::npos) << m;
    EXPECT_NE(m.find("x 820000.0 .. 821500.0"), std::string::npos) << m;
  }
  OSRDestroySpatialReference(zone32);
}

// A context of 1e-9 m cells (a georeferencing gone wrong) covers next to nothing: warned,
// and refused under --strict (before, accepted silently either way).
TEST(ContextGrid, AContextOfVanishingCellsIsWarnedAbout) {
  testing::register_gdal();
  TempDir dir;
  OGRSpatialReferenceH zone32 = utm_north(32);
  const std::string wkt = wkt_of(zone32);
  const double gt[6] = {kWest + 100.0, 1e-9, 0.0, kNorth - 100.0, 0.0, -1e-9};
  const std::string path = (dir / "tiny.tif").string();
  write_raster(path, "GTiff", GDT_Float32, 10, 10, std::vector<double>(100, 5.0), gt, wkt.c_str());
  std::vector<std::string> said;
  InputWarnings& w = input_warnings();
  w.sink = [&](const std::string& m) { said.push_back(m); };
  load_context(path, utm32_grid(wkt));
  ASSERT_EQ(said.size(), 1u);
  EXPECT_NE(said[0].find(path + ": the context's cells are 1e-09 x 1e-09 m"), std::string::npos)
      << said[0];
  w.strict = true;
  w.said.clear();
  EXPECT_THROW(load_context(path, utm32_grid(wkt)), InputError);
  w.strict = false;
  w.sink = nullptr;
  OSRDestroySpatialReference(zone32);
}

TEST(ContextGrid, UnreadableAndUnplacedContextsAreRefused) {
  testing::register_gdal();
  TempDir dir;
  const ElevationGrid grid = utm32_grid("");
  const std::string junk = dir.write("junk.tif", "not a raster").string();
  EXPECT_THROW(
      {
        try {
          load_context(junk, grid);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("not a raster format GDAL can read"),
                    std::string::npos);
          throw;
        }
      },
      InputError);
  // A PNG carries no placement: a context must say where it lies.
  const std::string png = (dir / "plain.png").string();
  write_raster(png, "PNG", GDT_UInt16, 4, 4, std::vector<double>(16, 1.0));
  EXPECT_THROW(load_context(png, grid), InputError);
}

}  // namespace
}  // namespace landsim::terrain
