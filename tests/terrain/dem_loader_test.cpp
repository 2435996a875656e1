#include "terrain/dem_loader.h"

#include <cpl_conv.h>
#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <fstream>

#include "core/input_error.h"
#include "terrain/raster_files.h"
#include "tests/support/rasters.h"
#include "tests/support/temp_dir.h"

namespace landsim::terrain {
namespace {

using landsim::testing::source_file;
using landsim::testing::TempDir;
using landsim::testing::write_raster;

std::string data(const std::string& name) { return source_file("data/terrain/" + name).string(); }

// Writes a raster with GDAL: `driver` GTiff directly, PNG through an in-memory copy.

std::string utm32n_wkt() {
  OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
  EXPECT_EQ(OSRImportFromEPSG(srs, 32632), OGRERR_NONE);
  char* wkt = nullptr;
  OSRExportToWkt(srs, &wkt);
  std::string out = wkt;
  CPLFree(wkt);
  OSRDestroySpatialReference(srs);
  return out;
}

TEST(DemLoader, VolcanoAsciiGrid) {
  const ElevationGrid g = load_elevation(data("volcano.asc"));
  EXPECT_EQ(g.cols(), 61);
  EXPECT_EQ(g.rows(), 87);
  EXPECT_DOUBLE_EQ(g.transform().cell_size_x, 10.0);
  EXPECT_DOUBLE_EQ(g.transform().origin_x, 0.0);
  EXPECT_DOUBLE_EQ(g.transform().origin_y, 870.0);  // yllcorner + 87 rows
  // Values read off the file: first row starts 94, row 40 col 20 is 134, the last cell 100.
  EXPECT_FLOAT_EQ(g.at(0, 0), 94.0f);
  EXPECT_FLOAT_EQ(g.at(20, 40), 134.0f);
  EXPECT_FLOAT_EQ(g.at(60, 86), 100.0f);
  EXPECT_FLOAT_EQ(g.at(30, 67), 195.0f);  // the summit
  EXPECT_FLOAT_EQ(g.min_height(), 94.0f);
  EXPECT_FLOAT_EQ(g.max_height(), 195.0f);
  EXPECT_EQ(g.nodata_count(), 0u);
}

TEST(DemLoader, BarroColoradoGridWithHalfCellOrigin) {
  const ElevationGrid g = load_elevation(data("bei_elev.asc"));
  EXPECT_EQ(g.cols(), 201);
  EXPECT_EQ(g.rows(), 101);
  EXPECT_DOUBLE_EQ(g.transform().cell_size_x, 5.0);
  EXPECT_DOUBLE_EQ(g.x_of_col(0), 0.0);  // xllcorner -2.5: the first centre is at 0
  EXPECT_FLOAT_EQ(g.at(0, 0), 137.27f);
  EXPECT_FLOAT_EQ(g.at(200, 100), 119.81f);
  EXPECT_FLOAT_EQ(g.max_height(), 159.48f);
}

TEST(DemLoader, GorillasNodataAndProjection) {
  const ElevationGrid g = load_elevation(data("gorillas_elevation.asc"));
  EXPECT_EQ(g.cols(), 181);
  EXPECT_EQ(g.rows(), 149);
  EXPECT_EQ(g.nodata_count(), 5927u);  // cells equal to -9999 in the file
  EXPECT_FALSE(g.valid(0, 0));
  EXPECT_FLOAT_EQ(g.at(90, 74), 1942.0f);
  EXPECT_FLOAT_EQ(g.min_height(), 1165.0f);  // -9999 never counts as a height
  EXPECT_FLOAT_EQ(g.max_height(), 2062.0f);
  EXPECT_NEAR(g.transform().origin_x, 580440.38505253, 1e-6);
  EXPECT_NE(g.crs_wkt().find("UTM zone 32N"), std::string::npos) << g.crs_wkt();
}

TEST(DemLoader, FillPolicyFillsEveryNodataCellWithinTheValidRange) {
  DemOptions options;
  options.nodata = NodataPolicy::fill;
  const ElevationGrid g = load_elevation(data("gorillas_elevation.asc"), options);
  EXPECT_EQ(g.nodata_count(), 0u);
  EXPECT_GE(g.min_height(), 1165.0f);
  EXPECT_LE(g.max_height(), 2062.0f);
  EXPECT_FLOAT_EQ(g.at(90, 74), 1942.0f);  // valid cells untouched
}

TEST(DemLoader, GeoTiffKeepsGeotransformCrsAndNodata) {
  TempDir dir;
  const std::string path = (dir / "dem.tif").string();
  const double gt[6] = {580000.0, 25.0, 0.0, 675000.0, 0.0, -25.0};
  const double nodata = -32768.0;
  const std::string wkt = utm32n_wkt();
  write_raster(path, "GTiff", GDT_Float32, 4, 3, {1, 2, 3, 4, 5, 6, -32768, 8, 9, 10, 11, 12}, gt,
               wkt.c_str(), &nodata);
  const ElevationGrid g = load_elevation(path);
  EXPECT_EQ(g.cols(), 4);
  EXPECT_EQ(g.rows(), 3);
  EXPECT_DOUBLE_EQ(g.transform().origin_x, 580000.0);
  EXPECT_DOUBLE_EQ(g.transform().origin_y, 675000.0);
  EXPECT_DOUBLE_EQ(g.transform().cell_size_x, 25.0);
  EXPECT_DOUBLE_EQ(g.transform().cell_size_y, 25.0);
  EXPECT_NE(g.crs_wkt().find("UTM zone 32N"), std::string::npos);
  EXPECT_EQ(g.nodata_count(), 1u);
  EXPECT_FALSE(g.valid(2, 1));
  EXPECT_FLOAT_EQ(g.at(3, 2), 12.0f);
  EXPECT_NEAR(*g.height(g.x_of_col(0), g.y_of_row(0)), 1.0, 1e-9);
}

TEST(DemLoader, SixteenBitPngNeedsCellSizeAndAppliesHeightScale) {
  TempDir dir;
  const std::string path = (dir / "dem.png").string();
  write_raster(path, "PNG", GDT_UInt16, 3, 2, {0, 1000, 65535, 20, 30, 40}, nullptr, nullptr,
               nullptr);
  try {
    load_elevation(path);
    FAIL() << "a PNG without cell_size must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("cell_size"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
  }
  DemOptions options;
  options.cell_size = 2.0;
  options.height_scale = 0.1;
  options.height_offset = 50.0;
  options.origin = std::array<double, 2>{10.0, 20.0};
  const ElevationGrid g = load_elevation(path, options);
  EXPECT_FLOAT_EQ(g.at(0, 0), 50.0f);
  EXPECT_FLOAT_EQ(g.at(2, 0), 6603.5f);  // the full 16-bit range survives
  EXPECT_FLOAT_EQ(g.at(1, 1), 53.0f);
  EXPECT_DOUBLE_EQ(g.transform().cell_size_x, 2.0);
  EXPECT_DOUBLE_EQ(g.transform().origin_x, 10.0);
  EXPECT_DOUBLE_EQ(g.transform().origin_y, 24.0);  // south edge 20 + 2 rows of 2 m
}

void expect_input_error(const std::string& path, const std::string& fragment) {
  try {
    load_elevation(path);
    FAIL() << path << " should have been refused";
  } catch (const InputError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    EXPECT_NE(msg.find(fragment), std::string::npos) << msg;
  }
}

TEST(DemLoader, TruncatedAsciiGridIsAClearError) {
  TempDir dir;
  const std::string text = testing::read_file(data("volcano.asc"));
  const auto path = dir.write("truncated.asc", text.substr(0, text.size() / 2));
  expect_input_error(path.string(), "truncated or corrupt");
}

TEST(DemLoader, GarbageIsAClearError) {
  TempDir dir;
  std::string garbage;
  for (int i = 0; i < 4096; ++i) garbage.push_back(static_cast<char>((i * 7919) % 251));
  const auto path = dir.write("garbage.asc", garbage);
  expect_input_error(path.string(), "not a raster format");
}

TEST(DemLoader, GridsOverAHundredMillionCellsAreRefusedFromTheirHeader) {
  // docs/SCENARIO.md: "Grids larger than 100 million cells are refused". The headers alone
  // (no heights follow): refused before any cell is read, at 100,020,000 cells; at exactly
  // 100 million the header passes and the missing heights are the error.
  TempDir dir;
  const auto header = [](int cols, int rows) {
    return "ncols " + std::to_string(cols) + "\nnrows " + std::to_string(rows) +
           "\nxllcorner 0\nyllcorner 0\ncellsize 1\nNODATA_value -9999\n1 2 3\n";
  };
  const auto over = dir.write("over.asc", header(20'000, 5'001));
  expect_input_error(over.string(), "exceeds the limit of 100000000 cells");
  const auto at = dir.write("at.asc", header(10'000, 10'000));
  try {
    open_elevation_raster(at.string());
  } catch (const InputError& e) {
    FAIL() << "100 million cells refused: " << e.what();
  }
}

TEST(DemLoader, MissingFileIsAClearError) {
  expect_input_error("/nonexistent/dem.asc", "not found");
}

TEST(DemLoader, MemoryFilesLoadLikeDiskFiles) {
  static const std::string text = testing::read_file(data("volcano.asc"));
  mount_memory_file("/vsimem/landsim-test/volcano.asc", text);
  const ElevationGrid g = load_elevation("/vsimem/landsim-test/volcano.asc");
  EXPECT_EQ(g.cols(), 61);
  EXPECT_FLOAT_EQ(g.at(30, 67), 195.0f);
}

}  // namespace
}  // namespace landsim::terrain
