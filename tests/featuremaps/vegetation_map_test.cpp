#include "featuremaps/vegetation_map.h"

#include <gdal.h>
#include <gtest/gtest.h>

#include "core/input_error.h"
#include "terrain/raster_files.h"
#include "tests/support/rasters.h"
#include "tests/support/temp_dir.h"

namespace landsim::featuremaps {
namespace {

using landsim::testing::TempDir;
using landsim::testing::write_raster;

std::string error_of(const std::string& path, const RasterPlacement& p = {}) {
  try {
    load_vegetation_map(path, p);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(VegetationMap, GeoTiffCellsAreFoundByPosition) {
  TempDir dir;
  const std::string path = (dir / "veg.tif").string();
  const double gt[6] = {1000.0, 20.0, 0.0, 2040.0, 0.0, -20.0};  // 3 x 2 cells of 20 m
  write_raster(path, "GTiff", GDT_UInt16, 3, 2, {1, 2, 49152 + 4, 0, 16384, 3}, gt);
  const VegetationMap m = load_vegetation_map(path);
  EXPECT_EQ(m.cols(), 3);
  EXPECT_EQ(m.rows(), 2);
  EXPECT_EQ(m.cell_at(1005.0, 2035.0)->raw, 1);           // north-west cell
  EXPECT_EQ(m.cell_at(1045.0, 2030.0)->grass_type(), 3);  // 49152 = grass 3, plus bit 2
  EXPECT_EQ(m.cell_at(1045.0, 2030.0)->species_bit(), 2);
  EXPECT_EQ(m.cell_at(1025.0, 2005.0)->grass_type(), 1);
  EXPECT_FALSE(m.cell_at(999.0, 2010.0).has_value());
  EXPECT_FALSE(m.cell_at(1010.0, 2041.0).has_value());
  EXPECT_EQ(m.multi_species_cells(), 1u);  // value 3 sets bits 0 and 1
  const auto b = m.bounds();
  EXPECT_DOUBLE_EQ(b[1], 2000.0);
  EXPECT_DOUBLE_EQ(b[2], 1060.0);
}

TEST(VegetationMap, SixteenBitPngNeedsPlacement) {
  TempDir dir;
  const std::string path = (dir / "veg.png").string();
  write_raster(path, "PNG", GDT_UInt16, 2, 2, {1, 2, 4, 8}, nullptr);
  EXPECT_NE(error_of(path).find("cell_size"), std::string::npos);
  RasterPlacement p;
  p.cell_size = 5.0;
  p.origin = std::array<double, 2>{100.0, 200.0};
  const VegetationMap m = load_vegetation_map(path, p);
  EXPECT_EQ(m.cell_at(101.0, 209.0)->raw, 1);
  EXPECT_EQ(m.cell_at(106.0, 201.0)->raw, 8);
}

TEST(VegetationMap, WrongBitDepthIsRefused) {
  TempDir dir;
  const std::string path = (dir / "veg8.tif").string();
  const double gt[6] = {0.0, 1.0, 0.0, 2.0, 0.0, -1.0};
  write_raster(path, "GTiff", GDT_Byte, 2, 2, {1, 2, 3, 4}, gt);
  const std::string msg = error_of(path);
  EXPECT_NE(msg.find("16-bit"), std::string::npos) << msg;
  EXPECT_NE(msg.find("Byte"), std::string::npos) << msg;
  EXPECT_NE(error_of((dir / "none.tif").string()).find("not found"), std::string::npos);
}

TEST(VegetationMap, WritesAndReadsBackAGeoTiff) {
  TempDir dir;
  const VegetationMap m(2, 2, terrain::GeoTransform{10.0, 30.0, 5.0, 5.0}, {1, 16385, 32768, 7});
  const std::string path = (dir / "out.tif").string();
  write_vegetation_map(m, path, "");
  const VegetationMap back = load_vegetation_map(path);
  EXPECT_EQ(back.at(1, 0).raw, 16385);
  EXPECT_EQ(back.at(0, 1).raw, 32768);
  EXPECT_DOUBLE_EQ(back.transform().origin_y, 30.0);
}

}  // namespace
}  // namespace landsim::featuremaps
