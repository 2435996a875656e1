// A map view of the Kagwene grid as GIS tools read it: GDAL's own reader finds the DEM's CRS,
// its exact geotransform, the bands' names and wavelengths, and world positions on the DEM.
#include "scenes/image_set/detail/geo_rasters.h"

#include <gdal.h>
#include <gtest/gtest.h>
#include <ogr_srs_api.h>

#include <cmath>
#include <string>

#include "scenes/image_set/image_set.h"
#include "terrain/dem_loader.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::TempDir;

struct GdalFile {
  explicit GdalFile(const std::filesystem::path& p) : ds(GDALOpen(p.c_str(), GA_ReadOnly)) {}
  ~GdalFile() {
    if (ds != nullptr) GDALClose(ds);
  }
  GDALDatasetH ds;
};

// The band named `name` (its description), 1-based; 0 when there is none.
int band_named(GDALDatasetH ds, const std::string& name) {
  for (int b = 1; b <= GDALGetRasterCount(ds); ++b)
    if (name == GDALGetDescription(GDALGetRasterBand(ds, b))) return b;
  return 0;
}

std::vector<float> read(GDALDatasetH ds, int band) {
  const int cols = GDALGetRasterXSize(ds), rows = GDALGetRasterYSize(ds);
  std::vector<float> v(static_cast<std::size_t>(cols) * rows);
  EXPECT_EQ(GDALRasterIO(GDALGetRasterBand(ds, band), GF_Read, 0, 0, cols, rows, v.data(), cols,
                         rows, GDT_Float32, 0, 0),
            CE_None);
  return v;
}

// Renders `views` over the Kagwene DEM, one sample, in `formats`, into dir/out.
std::filesystem::path render_kagwene(const TempDir& dir, const std::string& views,
                                     const std::string& formats) {
  const std::string dem = landsim::testing::source_file("data/terrain/gorillas_elevation.asc");
  const std::string text = "[terrain]\nelevation = \"" + dem +
                           "\"\n[sun]\nelevation = 50\nazimuth = 120\n" + views +
                           "[render]\nspp = 1\nformats = " + formats + "\n";
  const std::filesystem::path out = dir / "out";
  ImageSetOptions o;
  o.out_dir = out;
  render_image_set(parse_scenario(text, "kagwene.toml", "."), o);
  return out;
}

TEST(GeoRasters, AGridMapOfKagweneOpensInGdalOnTheDemsCells) {
  GDALAllRegister();
  const std::string dem = landsim::testing::source_file("data/terrain/gorillas_elevation.asc");
  TempDir dir;
  const std::filesystem::path out =
      render_kagwene(dir,
                     "[[bands]]\nname = \"red\"\ncentre = 660\nwidth = 60\n[[views]]\n"
                     "name = \"map\"\nprojection = \"orthographic\"\nalign = \"grid\"\n",
                     "[\"exr\", \"geotiff\", \"envi\"]");
  const terrain::ElevationGrid grid = terrain::load_elevation(dem);
  const GdalFile tif(out / "map.tif");
  ASSERT_NE(tif.ds, nullptr);
  EXPECT_EQ(GDALGetRasterXSize(tif.ds), grid.cols());
  EXPECT_EQ(GDALGetRasterYSize(tif.ds), grid.rows());
  // The DEM's CRS and its geotransform, exactly.
  OGRSpatialReferenceH ours = OSRNewSpatialReference(GDALGetProjectionRef(tif.ds));
  OGRSpatialReferenceH theirs = OSRNewSpatialReference(grid.crs_wkt().c_str());
  EXPECT_TRUE(OSRIsSame(ours, theirs));
  OSRDestroySpatialReference(ours);
  OSRDestroySpatialReference(theirs);
  double gt[6];
  ASSERT_EQ(GDALGetGeoTransform(tif.ds, gt), CE_None);
  const terrain::GeoTransform& t = grid.transform();
  EXPECT_NEAR(gt[0], t.origin_x, 1e-6);
  EXPECT_NEAR(gt[1], t.cell_size_x, 1e-9);
  EXPECT_NEAR(gt[2], 0.0, 1e-12);
  EXPECT_NEAR(gt[3], t.origin_y, 1e-6);
  EXPECT_NEAR(gt[4], 0.0, 1e-12);
  EXPECT_NEAR(gt[5], -t.cell_size_y, 1e-9);
  // The band, named, with its centre wavelength.
  const int red = band_named(tif.ds, "band.red");
  ASSERT_GT(red, 0);
  const char* nm = GDALGetMetadataItem(GDALGetRasterBand(tif.ds, red), "wavelength", nullptr);
  ASSERT_NE(nm, nullptr);
  EXPECT_NEAR(std::stod(nm), 660.0, 0.5);
  // The camera model, as in the manifest.
  const char* camera = GDALGetMetadataItem(tif.ds, "landsim_camera", nullptr);
  ASSERT_NE(camera, nullptr);
  EXPECT_NE(std::string(camera).find("\"orthographic\""), std::string::npos);
  // Each pixel's first hit lies in its own DEM cell, on the ground the DEM gives there.
  const auto x = read(tif.ds, band_named(tif.ds, "world_x"));
  const auto y = read(tif.ds, band_named(tif.ds, "world_y"));
  const auto z = read(tif.ds, band_named(tif.ds, "world_z"));
  const Vec3 origin = grid.centre();
  int on_grid = 0, nodata = 0, rim = 0;
  // Where the DEM has no data the map says so: NoData (NaN) in its float bands, and the
  // plain, its own class, in the object layer.
  int has_nodata = 0;
  EXPECT_TRUE(std::isnan(GDALGetRasterNoDataValue(GDALGetRasterBand(tif.ds, 1), &has_nodata)));
  EXPECT_TRUE(has_nodata);
  const GdalFile id_file(out / "map_ids.tif");
  const auto object = read(id_file.ds, band_named(id_file.ds, "object"));
  for (int r = 0; r < grid.rows(); ++r)
    for (int c = 0; c < grid.cols(); ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * grid.cols() + c;
      if (!grid.valid(c, r)) {
        EXPECT_TRUE(std::isnan(x[i])) << c << ", " << r;
        EXPECT_EQ(object[i], 7.0f) << c << ", " << r;  // plain
        ++nodata;
        continue;
      }
      // Every cell with data is ground, its rim beside a hole and the grid's edge too (the
      // mesh draws each such cell to its own edges), never the plain or NoData.
      EXPECT_NE(object[i], 7.0f) << c << ", " << r;
      ASSERT_FALSE(std::isnan(x[i])) << c << ", " << r;
      const double wx = x[i] + origin.x, wy = y[i] + origin.y, wz = z[i] + origin.z;
      // The pixel centre itself (the first sample goes through it on a grid map).
      EXPECT_NEAR(wx, grid.x_of_col(c), 0.01);
      EXPECT_NEAR(wy, grid.y_of_row(r), 0.01);
      const std::optional<double> ground = grid.height(wx, wy);
      if (!ground) {  // a rim cell: its centre is a vertex of the mesh, at its own height
        EXPECT_NEAR(wz, grid.at(c, r), 0.01) << c << ", " << r;
        ++rim;
        continue;
      }
      // The ground mesh's two triangles per quad of cell centres part from the bilinear
      // surface by at most a quarter of the quad's twist.
      const int c0 = static_cast<int>(std::floor((wx - t.origin_x) / t.cell_size_x - 0.5));
      const int r0 = static_cast<int>(std::floor((t.origin_y - wy) / t.cell_size_y - 0.5));
      const double twist = std::abs(grid.at(c0, r0) + grid.at(c0 + 1, r0 + 1) -
                                    grid.at(c0 + 1, r0) - grid.at(c0, r0 + 1));
      EXPECT_NEAR(wz, *ground, 0.25 * twist + 0.01) << c << ", " << r;
      ++on_grid;
    }
  EXPECT_GT(on_grid, grid.cols() * grid.rows() / 4);
  EXPECT_GT(nodata, 0);  // the Kagwene DEM has holes
  EXPECT_GT(rim, 100);   // and cells with data beside them
  // The id layers in a file of their own, and ENVI with its wavelengths.
  const GdalFile ids(out / "map_ids.tif");
  ASSERT_NE(ids.ds, nullptr);
  EXPECT_EQ(GDALGetRasterDataType(GDALGetRasterBand(ids.ds, 1)), GDT_UInt32);
  EXPECT_GT(band_named(ids.ds, "species"), 0);
  const GdalFile envi(out / "map.img");
  ASSERT_NE(envi.ds, nullptr);
  EXPECT_TRUE(std::filesystem::exists(out / "map.hdr"));
  EXPECT_EQ(GDALGetRasterCount(envi.ds), GDALGetRasterCount(tif.ds));
}

// A perspective view has no geotransform: ground control points place it. Each lies where its
// pixel's hit projects (inside that pixel) at that hit's terrain coordinates, on the DEM.
TEST(GeoRasters, APerspectiveViewCarriesGroundControlPointsOnTheDem) {
  GDALAllRegister();
  const std::string dem = landsim::testing::source_file("data/terrain/gorillas_elevation.asc");
  TempDir dir;
  const std::filesystem::path out =
      render_kagwene(dir,
                     "[[views]]\nname = \"v\"\nposition = [582700.0, 676100.0]\n"
                     "altitude_above_ground = 300\ntarget = [583150.0, 676400.0, 1900.0]\n"
                     "width = 96\nheight = 64\n",
                     "[\"exr\", \"geotiff\"]");
  const terrain::ElevationGrid grid = terrain::load_elevation(dem);
  const GdalFile tif(out / "v.tif");
  ASSERT_NE(tif.ds, nullptr);
  double gt[6];
  EXPECT_NE(GDALGetGeoTransform(tif.ds, gt), CE_None);  // no geotransform
  const int n = GDALGetGCPCount(tif.ds);
  ASSERT_GE(n, 32);  // most of the 8 x 8 lattice sees ground
  OGRSpatialReferenceH ours = OSRNewSpatialReference(GDALGetGCPProjection(tif.ds));
  OGRSpatialReferenceH theirs = OSRNewSpatialReference(grid.crs_wkt().c_str());
  EXPECT_TRUE(OSRIsSame(ours, theirs));
  OSRDestroySpatialReference(ours);
  OSRDestroySpatialReference(theirs);
  const auto x = read(tif.ds, band_named(tif.ds, "world_x"));
  const Vec3 origin = grid.centre();
  const GDAL_GCP* gcps = GDALGetGCPs(tif.ds);
  for (int k = 0; k < n; ++k) {
    const GDAL_GCP& g = gcps[k];
    ASSERT_GE(g.dfGCPPixel, 0.0);
    ASSERT_LT(g.dfGCPPixel, 96.0);
    ASSERT_GE(g.dfGCPLine, 0.0);
    ASSERT_LT(g.dfGCPLine, 64.0);
    // The pixel it falls in holds the very hit (its first sample's).
    const std::size_t i =
        static_cast<std::size_t>(g.dfGCPLine) * 96 + static_cast<std::size_t>(g.dfGCPPixel);
    EXPECT_NEAR(x[i] + origin.x, g.dfGCPX, 0.01) << k;
    // On the ground the DEM gives there.
    const std::optional<double> h = grid.height(g.dfGCPX, g.dfGCPY);
    ASSERT_TRUE(h.has_value()) << k;
    EXPECT_NEAR(g.dfGCPZ, *h, 3.0) << k;
  }
}

TEST(GeoRasters, OnlyAStraightDownOrthographicViewIsAMap) {
  renderer::View v{"v", {0.0, 0.0, 100.0}, {0.0, 0.0, 0.0}, 40.0, 10, 20};
  EXPECT_FALSE(detail::map_geotransform(v, {}));  // perspective
  v.lens.projection = renderer::Projection::orthographic;
  v.lens.extent_width = 100.0;
  v.lens.extent_height = 200.0;
  v.heading_deg = 90.0;  // east at the top: the geotransform turns
  const auto gt = detail::map_geotransform(v, {1000.0, 2000.0, 0.0});
  ASSERT_TRUE(gt);
  // Pixel (0, 0)'s corner: 100 m east (the top) and 50 m north (the left edge is north).
  EXPECT_NEAR((*gt)[0], 1100.0, 1e-9);
  EXPECT_NEAR((*gt)[3], 2050.0, 1e-9);
  // Columns run south, rows run west.
  EXPECT_NEAR((*gt)[4], -10.0, 1e-9);
  EXPECT_NEAR((*gt)[2], -10.0, 1e-9);
  v.target = {0.0, 10.0, 0.0};  // oblique
  EXPECT_FALSE(detail::map_geotransform(v, {}));
}

}  // namespace
}  // namespace landsim::scenes
