// One scenario that sets every documented key: it must load with those values, every key
// docs/SCENARIO.md documents must appear in it, and the scene built from it must carry the
// vegetation, grass and ground materials it asks for.
#include <gdal.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>

#include "core/input_error.h"
#include "renderer/spectra/vegetation_optics.h"
#include "scenes/builder/detail/tree_variant.h"
#include "scenes/builder/scene_builder.h"
#include "scenes/scenario/scenario.h"
#include "terrain/raster_files.h"
#include "tests/support/rasters.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using landsim::testing::source_file;
using landsim::testing::TempDir;

// A raster on the volcano grid (61 x 87 cells of 10 m, origin 0, 0) with `value` in the
// given columns and 0 elsewhere.
void write_grid(const std::string& path, GDALDataType type, int first_col, int last_col,
                double value) {
  landsim::testing::register_gdal();
  GDALDatasetH ds =
      GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 61, 87, 1, type, nullptr);
  double gt[6] = {0.0, 10.0, 0.0, 870.0, 0.0, -10.0};
  GDALSetGeoTransform(ds, gt);
  std::vector<double> v(61 * 87, 0.0);
  for (int r = 0; r < 87; ++r)
    for (int c = first_col; c <= last_col; ++c) v[static_cast<std::size_t>(r) * 61 + c] = value;
  ASSERT_EQ(GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 61, 87, v.data(), 61, 87,
                         GDT_Float64, 0, 0),
            CE_None);
  GDALClose(ds);
}

std::string full_text(const TempDir& dir, const std::string& vegetation_keys) {
  const std::string data = source_file("data").string();
  return "[terrain]\n"
         "elevation = \"" +
         data +
         "/terrain/volcano.asc\"\n"
         "cell_size = 10.0\norigin = [0.0, 0.0]\nheight_scale = 1.1\nheight_offset = 2.0\n"
         "nodata = \"fill\"\nalbedo = [0.2, 0.2, 0.1]\ncontext = [\"" +
         (dir / "context.tif").string() +
         "\"]\n\n"
         "[featuremaps]\n" +
         vegetation_keys + "soil = \"" + (dir / "soil.tif").string() + "\"\nrock = \"" +
         (dir / "rock.tif").string() +
         "\"\n"
         "water = \"" +
         (dir / "water.tif").string() + "\"\nroad = \"" + (dir / "road.tif").string() +
         "\"\n\n"
         "[[species]]\nbit = 2\nfile = \"" +
         data +
         "/species/palm.xml\"\nvariants = 2\ndensity_per_ha = 80\n"
         "scale_variation = 0.2\ncolour_variation = 0.1\nmin_spacing = 3.0\nevergreen = "
         "true\nbark_texture = \"" +
         (dir / "bark.png").string() +
         "\"\n\n"
         "[[species]]\nbit = 3\nfile = \"" +
         data +
         "/species/london_plane.toml\"\nvariants = 2\ndensity_per_ha = 5\nage = [15.0, 40.0]\n"
         "[species.leaf_optics]\nstructure = 1.8\nchlorophyll = 30.0\ncarotenoids = 7.0\n"
         "anthocyanins = 1.0\nbrown = 0.1\nwater = 0.012\ndry_matter = 0.008\n\n"
         "[[grass]]\ntype = 1\ndensity_per_m2 = 50\nblade_length = 0.2\nblade_width = "
         "0.003\ncurvature = 0.5\n"
         "colour = [0.1, 0.3, 0.05]\n\n"
         "[[grass]]\ntype = 3\ncover = { rectangle = [0.0, 0.0, 50.0, 50.0] }\n\n"
         "[ground]\nsoil = [0.3, 0.2, 0.1]\nrock = [0.4, 0.4, 0.4]\nwater = [0.01, 0.02, "
         "0.03]\nroad = [0.1, 0.1, 0.1]\n"
         "variation = { soil = 0.3, grass = 0.1 }\nvariation_scales = [80.0, 8.0]\n"
         "textures = { rock = \"" +
         (dir / "bark.png").string() +
         "\" }\ntexture_size = 3.0\ndetail = true\ndetail_amplitude = { rock = 2.0 }\n"
         "detail_roughness = 0.6\nsoil_moisture = 0.4\n"
         "[[ground.rules]]\nmeasure = \"slope\"\nabove = 30.0\nbelow = 80.0\nsoftness = 3.0\n"
         "on = [\"terrain\", \"grass\"]\nbecomes = \"rock\"\ntint = [1.1, 1.0, 0.9]\n\n"
         "[[ground.brdf]]\nmodel = \"rpv\"\nk = 0.9\nasymmetry = -0.1\nhot_spot = 0.05\n"
         "[[ground.brdf]]\nmodel = \"ross-li\"\nvolumetric = 0.3\ngeometric = 0.05\n"
         "reflectance = \"isotropic\"\n"
         "on = [\"rock\", \"road\"]\n\n"
         "[wind]\nspeed = 4.0\ngust = 2.0\ndirection = 200.0\ngust_scale = 40.0\nphase_groups = "
         "2\n\n"
         "[sun]\ndate = 2026-06-21\ntime = 13:00:00\nutc_offset = 12.0\nlatitude = "
         "-36.88\nlongitude = 174.76\n"
         "irradiance = [3.0, 3.0, 3.0]\n\n[sky]\nmodel = \"gradient\"\n\n"
         "[haze]\nvisibility = 9000.0\nscale_height = 900.0\ncolour = [0.9, 0.9, 0.9]\nasymmetry = "
         "0.6\n\n"
         "[[views]]\nname = \"all\"\nposition = [300.0, -100.0, 250.0]\ntarget = [300.0, 400.0, "
         "120.0]\n"
         "fov = 35.0\nwidth = 64\nheight = 32\n\n"
         "[render]\nspp = 2\nseed = 5\nthreads = 1\nmax_bounces = 2\nexposure = 0.5\nframes = "
         "[0.0, 1.5]\nseason = \"autumn\"\ncheckpoint_seconds = 30.0\ndegradation = false\n"
         "quality = 0.8\nmax_memory = \"12 GB\"\n\n"
         "[[objects]]\nname = \"car\"\nfile = \"" +
         data +
         "/objects/car.gltf\"\nposition = [300.0, 400.0]\nheading = 45.0\nscale = 1.5\n"
         "unit_scale = 0.5\nup_axis = \"y\"\nalign_to_ground = true\nclear_radius = 3.0\n"
         "[[objects.material]]\nname = \"paint_red\"\nalbedo = [0.1, 0.2, 0.3]\nroughness = "
         "0.4\nmetallic = 0.7\n"
         "[[bands]]\nname = \"nir\"\ncentre = 835.0\nwidth = 130.0\n"
         "[[bands]]\nname = \"luminance\"\nresponse = \"" +
         data + "/bands/cie_photopic.csv\"\n";
}

struct Fixture {
  TempDir dir;
  std::string vegetation = (dir / "veg.tif").string();
  Fixture() {
    // Columns 0-19: species bit 2 with grass 1; 20-39: grass only; the rest bare.
    landsim::testing::register_gdal();
    GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), vegetation.c_str(), 61, 87, 1,
                                 GDT_UInt16, nullptr);
    double gt[6] = {0.0, 10.0, 0.0, 870.0, 0.0, -10.0};
    GDALSetGeoTransform(ds, gt);
    std::vector<std::uint16_t> v(61 * 87, 0);
    for (int r = 0; r < 87; ++r) {
      for (int c = 0; c < 40; ++c)
        v[static_cast<std::size_t>(r) * 61 + c] =
            static_cast<std::uint16_t>(c < 20 ? (4 | 16384) : 16384);
    }
    const CPLErr written = GDALRasterIO(GDALGetRasterBand(ds, 1), GF_Write, 0, 0, 61, 87, v.data(),
                                        61, 87, GDT_UInt16, 0, 0);
    GDALClose(ds);
    if (written != CE_None) throw std::runtime_error("could not write the test vegetation map");
    write_grid((dir / "soil.tif").string(), GDT_Byte, 40, 44, 1);
    landsim::testing::write_raster((dir / "bark.png").string(), "PNG", GDT_Byte, 2, 2,
                                   {40, 200, 120, 90});
    write_grid((dir / "rock.tif").string(), GDT_Byte, 45, 49, 1);
    write_grid((dir / "water.tif").string(), GDT_Byte, 50, 54, 1);
    write_grid((dir / "road.tif").string(), GDT_Byte, 55, 60, 1);
    // A 1.2 km context of 30 m cells at 100 m around the volcano (0-610 m x 0-870 m).
    const double context_gt[6] = {-300.0, 30.0, 0.0, 1170.0, 0.0, -30.0};
    landsim::testing::write_raster((dir / "context.tif").string(), "GTiff", GDT_Float32, 40, 40,
                                   std::vector<double>(1600, 100.0), context_gt);
  }
  std::string text() const { return full_text(dir, "vegetation = \"" + vegetation + "\"\n"); }
};

TEST(FullScenario, LoadsEveryKey) {
  Fixture f;
  const Scenario s = load_scenario(f.dir.write("full.toml", f.text()));
  ASSERT_TRUE(s.featuremaps.has_value());
  EXPECT_EQ(s.featuremaps->vegetation, f.vegetation);
  EXPECT_EQ(s.featuremaps->water, (f.dir / "water.tif").string());
  ASSERT_EQ(s.species.size(), 2u);
  EXPECT_EQ(s.species[0].bit, 2);
  EXPECT_EQ(s.species[0].variants, 2);
  EXPECT_DOUBLE_EQ(s.species[0].min_spacing, 3.0);
  EXPECT_EQ(s.species[0].species.name, "palm");
  EXPECT_DOUBLE_EQ(s.wind.direction_deg, 200.0);
  EXPECT_DOUBLE_EQ(s.wind.gust_scale, 40.0);
  EXPECT_EQ(s.wind.phase_groups, 2);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].name, "car");
  EXPECT_EQ(s.objects[0].file, source_file("data/objects/car.gltf").string());
  EXPECT_DOUBLE_EQ(s.objects[0].x, 300.0);
  EXPECT_FALSE(s.objects[0].z.has_value());
  EXPECT_DOUBLE_EQ(s.objects[0].heading_deg, 45.0);
  EXPECT_DOUBLE_EQ(s.objects[0].scale, 1.5);
  EXPECT_DOUBLE_EQ(s.objects[0].unit_scale, 0.5);
  EXPECT_FALSE(s.objects[0].z_up);
  EXPECT_TRUE(s.objects[0].align_to_ground);
  EXPECT_EQ(s.objects[0].clear_radius, 3.0);
  ASSERT_EQ(s.objects[0].materials.size(), 1u);
  EXPECT_EQ(s.objects[0].materials[0].material, "paint_red");
  EXPECT_EQ(s.objects[0].materials[0].roughness, 0.4f);
  EXPECT_EQ(s.objects[0].materials[0].metallic, 0.7f);
  EXPECT_EQ(s.objects[0].materials[0].albedo->z, 0.3f);
  ASSERT_EQ(s.grass.size(), 2u);
  EXPECT_DOUBLE_EQ(s.grass[0].curvature, 0.5);
  EXPECT_FALSE(s.grass[0].cover);
  ASSERT_TRUE(s.grass[1].cover);
  EXPECT_EQ(s.grass[1].cover->polygon.size(), 4u);  // the rectangle's corners
  EXPECT_EQ(s.grass[1].cover->polygon[2], (std::array<double, 2>{50.0, 50.0}));
  EXPECT_FLOAT_EQ(s.ground.rock.x, 0.4f);
  const renderer::GroundShading& sh = s.ground.shading;
  EXPECT_FLOAT_EQ(sh.variation[4], 0.3f);  // soil
  EXPECT_FLOAT_EQ(sh.variation[6], 0.1f);  // under grass type 2
  EXPECT_FLOAT_EQ(sh.variation[3], 0.2f);  // rock keeps its default
  EXPECT_EQ(sh.scales[1], 8.0);
  EXPECT_EQ(sh.texture_size, 3.0);
  EXPECT_NE(s.ground.texture_files[3].find("bark.png"), std::string::npos);
  ASSERT_EQ(sh.rules.size(), 1u);
  EXPECT_EQ(sh.rules[0].measure, renderer::TerrainMeasure::slope);
  EXPECT_EQ(sh.rules[0].above, 30.0);
  EXPECT_EQ(sh.rules[0].below, 80.0);
  EXPECT_EQ(sh.rules[0].softness, 3.0);
  EXPECT_EQ(sh.rules[0].on, (1u << 0) | (1u << 5) | (1u << 6) | (1u << 7));
  EXPECT_EQ(sh.rules[0].becomes, 3);
  // [[ground.brdf]]: RPV on every material but water, Ross-Li over it on rock and road.
  EXPECT_EQ(s.ground.brdf[4].model, renderer::GroundBrdf::Model::rpv);
  EXPECT_FLOAT_EQ(s.ground.brdf[4].k, 0.9f);
  EXPECT_FLOAT_EQ(s.ground.brdf[4].asymmetry, -0.1f);
  EXPECT_FLOAT_EQ(s.ground.brdf[4].hot_spot, 0.05f);
  EXPECT_EQ(s.ground.brdf[3].model, renderer::GroundBrdf::Model::ross_li);
  EXPECT_FLOAT_EQ(s.ground.brdf[1].volumetric, 0.3f);
  EXPECT_FLOAT_EQ(s.ground.brdf[1].geometric, 0.05f);
  EXPECT_EQ(s.ground.brdf[2].model, renderer::GroundBrdf::Model::lambert);
  EXPECT_TRUE(s.ground.brdf_white_sky[4]);
  EXPECT_FALSE(s.ground.brdf_white_sky[3]);
  EXPECT_FLOAT_EQ(sh.rules[0].tint.x, 1.1f);
  EXPECT_TRUE(s.ground.detail);
  EXPECT_DOUBLE_EQ(s.ground.soil_moisture, 0.4);
  ASSERT_EQ(s.bands.size(), 2u);
  EXPECT_EQ(s.bands[0].name, "nir");
  EXPECT_EQ(s.bands[0].description, "box 770-900 nm");
  EXPECT_EQ(s.bands[1].response.size(), 41u);  // 380-780 nm at 10 nm
  ASSERT_TRUE(s.species[1].species.colours.leaf_optics.has_value());
  const trees::LeafContents& leaf = *s.species[1].species.colours.leaf_optics;
  EXPECT_EQ(leaf, (trees::LeafContents{1.8, 30.0, 7.0, 1.0, 0.1, 0.012, 0.008}));
  EXPECT_FLOAT_EQ(s.ground.detail_amplitude[3], 2.0f);
  EXPECT_FLOAT_EQ(s.ground.detail_amplitude[4], 0.3f);  // soil keeps its default
  EXPECT_FLOAT_EQ(s.ground.detail_roughness[0], 0.6f);
  EXPECT_DOUBLE_EQ(s.wind.gust, 2.0);
  EXPECT_EQ(s.render.frames, (std::vector<double>{0.0, 1.5}));
  EXPECT_EQ(s.render.season, trees::Season::autumn);
  EXPECT_DOUBLE_EQ(s.render.checkpoint_seconds, 30.0);
  EXPECT_FALSE(s.render.degradation);
  EXPECT_DOUBLE_EQ(s.render.quality, 0.8);
  EXPECT_EQ(s.render.max_memory, 12'000'000'000u);
  EXPECT_TRUE(s.species[0].evergreen);
  EXPECT_DOUBLE_EQ(s.species[1].age_min, 15.0);
  EXPECT_DOUBLE_EQ(s.species[1].age_max, 40.0);
  EXPECT_EQ(s.species[0].bark_texture, (f.dir / "bark.png").string());
  EXPECT_TRUE(s.haze.enabled);
  EXPECT_DOUBLE_EQ(s.haze.visibility, 9000.0);
  EXPECT_DOUBLE_EQ(s.haze.asymmetry, 0.6);
  EXPECT_DOUBLE_EQ(s.haze.scale_height, 900.0);
  EXPECT_EQ(s.haze.albedo, (Vec3f{0.9f, 0.9f, 0.9f}));
  EXPECT_EQ(s.sky.model, renderer::SkyKind::gradient);  // [haze] beside a sky of no aerosol
  ASSERT_TRUE(s.sun.irradiance.has_value());
  EXPECT_EQ(*s.sun.irradiance, (Vec3f{3.0f, 3.0f, 3.0f}));
  // [terrain]
  EXPECT_EQ(s.terrain.elevation, source_file("data/terrain/volcano.asc").string());
  EXPECT_EQ(s.terrain.dem.cell_size, 10.0);
  EXPECT_EQ(s.terrain.dem.origin, (std::array<double, 2>{0.0, 0.0}));
  EXPECT_DOUBLE_EQ(s.terrain.dem.height_scale, 1.1);
  EXPECT_DOUBLE_EQ(s.terrain.dem.height_offset, 2.0);
  EXPECT_EQ(s.terrain.dem.nodata, terrain::NodataPolicy::fill);
  EXPECT_EQ(s.terrain.albedo, (Vec3f{0.2f, 0.2f, 0.1f}));
  EXPECT_EQ(s.terrain.context, (std::vector<std::string>{(f.dir / "context.tif").string()}));
  // [featuremaps] ground rasters
  EXPECT_EQ(s.featuremaps->soil, (f.dir / "soil.tif").string());
  EXPECT_EQ(s.featuremaps->rock, (f.dir / "rock.tif").string());
  EXPECT_EQ(s.featuremaps->road, (f.dir / "road.tif").string());
  // [[species]]
  EXPECT_DOUBLE_EQ(s.species[0].density_per_ha, 80.0);
  EXPECT_DOUBLE_EQ(s.species[0].scale_variation, 0.2);
  EXPECT_DOUBLE_EQ(s.species[0].colour_variation, 0.1);
  EXPECT_EQ(s.species[1].bit, 3);
  EXPECT_EQ(s.species[1].variants, 2);
  EXPECT_DOUBLE_EQ(s.species[1].density_per_ha, 5.0);
  EXPECT_EQ(s.species[1].species.name, "london_plane");
  // [[grass]]
  EXPECT_EQ(s.grass[0].type, 1);
  EXPECT_DOUBLE_EQ(s.grass[0].density_per_m2, 50.0);
  EXPECT_DOUBLE_EQ(s.grass[0].blade_length, 0.2);
  EXPECT_DOUBLE_EQ(s.grass[0].blade_width, 0.003);
  EXPECT_EQ(s.grass[0].colour, (Vec3f{0.1f, 0.3f, 0.05f}));
  EXPECT_EQ(s.grass[1].type, 3);
  // [ground]
  EXPECT_EQ(s.ground.soil, (Vec3f{0.3f, 0.2f, 0.1f}));
  EXPECT_EQ(s.ground.water, (Vec3f{0.01f, 0.02f, 0.03f}));
  EXPECT_EQ(s.ground.road, (Vec3f{0.1f, 0.1f, 0.1f}));
  EXPECT_EQ(sh.scales[0], 80.0);
  // [wind]
  EXPECT_DOUBLE_EQ(s.wind.speed, 4.0);
  // [[views]]
  ASSERT_EQ(s.views.size(), 1u);
  EXPECT_EQ(s.views[0].name, "all");
  EXPECT_EQ(s.views[0].position, (Vec3{300.0, -100.0, 250.0}));
  EXPECT_EQ(s.views[0].target, (Vec3{300.0, 400.0, 120.0}));
  EXPECT_DOUBLE_EQ(s.views[0].fov_y_deg, 35.0);
  EXPECT_EQ(s.views[0].width, 64);
  EXPECT_EQ(s.views[0].height, 32);
  // [render]
  EXPECT_EQ(s.render.spp, 2);
  EXPECT_EQ(s.render.seed, 5u);
  EXPECT_EQ(s.render.threads, 1);
  EXPECT_EQ(s.render.max_bounces, 2);
  EXPECT_EQ(s.render.exposure_ev100, 0.5);
  // [[objects]]
  EXPECT_DOUBLE_EQ(s.objects[0].y, 400.0);
  // [[bands]]
  EXPECT_DOUBLE_EQ(s.bands[0].response.front().wavelength_nm, 770.0);
  EXPECT_EQ(s.bands[1].name, "luminance");
  EXPECT_EQ(s.bands[1].description,
            "response " + source_file("data/bands/cie_photopic.csv").string());
  // Auckland at 13:00 NZST on the June solstice: the sun in the north, 29-30 degrees up
  // (90 - 36.88 - 23.44 = 29.7 at solar noon, which falls about 12:40 there).
  EXPECT_NEAR(s.sun.elevation_deg, 29.5, 1.0);
  EXPECT_NEAR(std::remainder(s.sun.azimuth_deg, 360.0), 0.0, 10.0);
}

// Every core takes an age: the London plane's [15, 40] given to a Weber & Penn species is
// kept; ages out of order are refused at the species.
TEST(FullScenario, AgesGoToEveryCore) {
  Fixture f;
  std::string text = f.text();
  const std::string plane = "/species/london_plane.toml";
  text.replace(text.find(plane), plane.size(), "/species/quaking_aspen.toml");
  const Scenario s = load_scenario(f.dir.write("aged.toml", text));
  EXPECT_DOUBLE_EQ(s.species[1].age_min, 15.0);
  EXPECT_DOUBLE_EQ(s.species[1].age_max, 40.0);
  // Its two variants: 15 years, and 40 (the aspen's file is a 30-year tree: drawn at 30).
  const auto top = [&](std::uint32_t variant) {
    const renderer::TreePrototype p = scenes::detail::make_tree_variant(s, 1, variant, 0.0, 0);
    float z = 0.0f;
    for (const Vec3f& v : p.geometry.group(trees::Group::trunk).triangles.vertices)
      z = std::max(z, v.z);
    return z;
  };
  EXPECT_LT(top(0), 0.85f * top(1));
  const std::string range = "age = [15.0, 40.0]";
  text.replace(text.find(range), range.size(), "age = [40.0, 15.0]");
  try {
    load_scenario(f.dir.write("reversed.toml", text));
    FAIL() << "ages out of order were accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("species[1]"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("youngest first"), std::string::npos) << e.what();
  }
}

TEST(FullScenario, EveryDocumentedKeyIsExercised) {
  const std::string doc = landsim::testing::read_file(source_file("docs/SCENARIO.md"));
  std::set<std::string> documented;
  const std::regex row(R"(^\| (`[^|]+`)[^|]*\|)");
  const std::regex key("`([a-z_0-9]+)`");
  std::istringstream lines(doc);
  for (std::string line; std::getline(lines, line);) {
    std::smatch m;
    if (!std::regex_search(line, m, row)) continue;
    const std::string cell = m[1];
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), key);
         it != std::sregex_iterator(); ++it) {
      documented.insert((*it)[1]);
    }
  }
  ASSERT_GT(documented.size(), 40u);
  Fixture f;
  // The class-raster alternative to `vegetation` is set by the default scenario, which the
  // DefaultScenario tests load and render; camera keys by the cameras example (its views
  // placed by ViewPlacement.TheKagweneCamerasExamplePlacesItsViews) and the views below.
  const std::string cameras =
      "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 30\nazimuth = 200\n"
      "[[views]]\nname = \"lens\"\nposition = [300.0, 100.0, 300.0]\ntarget = [300.0, 400.0, "
      "150.0]\nup = [0.1, 0.0, 1.0]\nfocal_length = 50\npixel_pitch = 5\n"
      "principal_point = [3.0, -2.0]\nf_number = 4\nfocus_distance = 120\n"
      "[[views]]\nname = \"fisheye\"\nposition = [300.0, 400.0, 200.0]\nyaw = 0\npitch = -90\n"
      "projection = \"fisheye\"\nmapping = \"equisolid\"\nimage_circle = 300\n"
      "[[views]]\nname = \"extent\"\nposition = [300.0, 400.0, 600.0]\n"
      "projection = \"orthographic\"\nextent = [400.0, 200.0]\n"
      "[[views]]\nname = \"pixels\"\nposition = [300.0, 400.0, 600.0]\n"
      "projection = \"orthographic\"\npixel_size = 2.0\n"
      "[[views]]\nname = \"map\"\nprojection = \"orthographic\"\nalign = \"grid\"\n"
      "cells_per_pixel = 2\n[render]\nformats = [\"exr\", \"geotiff\"]\nsampling_seed = 9\n"
      "sampler = \"sobol\"\n";
  const Scenario with_cameras = load_scenario(f.dir.write("cameras.toml", cameras));
  EXPECT_EQ(with_cameras.views.size(), 5u);
  EXPECT_EQ(with_cameras.render.sampler, SampleSequence::sobol);
  // The sensor's keys (docs/SENSOR.md); iso in a second sensor, gain and iso being exclusive.
  const std::string sensor_view =
      "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
      "\"\n[sun]\nelevation = 30\nazimuth = 200\n"
      "[[views]]\nname = \"v\"\nposition = [300.0, 100.0, 300.0]\ntarget = [300.0, 400.0, 150.0]\n"
      "sensor = { exposure_time = 0.002 }\n[render]\nreflectance = true\n"
      "atmosphere_layers = true\nillumination_layers = true\nnoise_threshold = "
      "0.05\nmin_spp = 8\nguiding = true\nguiding_training = 0.2\n";
  const std::string sensor = sensor_view +
                             "[sensor]\nchannels = \"xyz\"\nquantum_efficiency = 0.5\n"
                             "pixel_pitch = 4.0\nexposure_time = \"auto\"\nf_number = 5.6\n"
                             "transmittance = 0.9\ngain = 1.5\nfull_well = 20000\n"
                             "read_noise = 3.0\ndark_current = 10\nadc_bits = 14\n"
                             "black_level = 64\nblur_sigma = 1.0\nnoise_seed = 7\n"
                             "natural_vignetting = true\nlens_vignetting = [-0.1, 0.0, 0.0]\n";
  const Scenario with_sensor = load_scenario(f.dir.write("sensor.toml", sensor));
  EXPECT_DOUBLE_EQ(*with_sensor.views[0].sensor->exposure_time_s, 0.002);
  EXPECT_TRUE(with_sensor.render.illumination_layers);
  EXPECT_TRUE(with_sensor.render.guiding);
  EXPECT_DOUBLE_EQ(with_sensor.render.guiding_training, 0.2);
  EXPECT_EQ(with_sensor.views[0].sensor->black_level_dn, 64);
  EXPECT_TRUE(with_sensor.views[0].sensor->vignetting.natural);
  EXPECT_TRUE(with_sensor.render.atmosphere_layers);
  const std::string iso = sensor_view + "[sensor]\niso = 400\n";
  EXPECT_DOUBLE_EQ(*load_scenario(f.dir.write("iso.toml", iso)).sensor->model.iso, 400.0);
  // The haze's medium keys (docs/ATMOSPHERE.md): an aerosol of tabulated phase, and the
  // plane-parallel layer of Legendre moments.
  const std::string terrain = "[terrain]\nelevation = \"" +
                              source_file("data/terrain/volcano.asc").string() +
                              "\"\n[sun]\nelevation = 30\nazimuth = 200\n";
  const std::string views =
      "[[views]]\nname = \"v\"\nposition = [300.0, 100.0, 300.0]\n"
      "target = [300.0, 400.0, 150.0]\n";
  // Preetham's sky and its turbidity (an aerosol of its own: no [haze] beside it).
  const std::string preetham_text =
      terrain + views + "[sky]\nmodel = \"preetham\"\nturbidity = 2.5\n";
  const Scenario preetham = load_scenario(f.dir.write("preetham.toml", preetham_text));
  EXPECT_EQ(preetham.sky.model, renderer::SkyKind::preetham);
  EXPECT_DOUBLE_EQ(preetham.sky.turbidity, 2.5);
  const std::string aerosol =
      terrain + views + "[sky]\nmodel = \"none\"\n" +
      "[haze]\nvisibility = 8000\nsingle_scattering_albedo = 0.9\nmultiple_scattering = \"paths\"\n"
      "angstrom = 1.1\nmolecular = false\nphase = \"table\"\n"
      "phase_angles = [0.0, 90.0, 180.0]\nphase_values = [5.0, 1.0, 0.5]\n";
  const Scenario with_aerosol = load_scenario(f.dir.write("aerosol.toml", aerosol));
  EXPECT_FLOAT_EQ(with_aerosol.haze.albedo.x, 0.9f);
  EXPECT_EQ(with_aerosol.haze.phase_values.size(), 3u);
  EXPECT_FALSE(with_aerosol.haze.molecular);
  EXPECT_EQ(with_aerosol.haze.scattering, renderer::HazeScattering::paths);
  const std::string layer = terrain + views + "[sky]\nmodel = \"none\"\n" +
                            "[haze]\nlayer = { optical_depth = 2.0, top = 500.0 }\n"
                            "phase = \"legendre\"\nphase_moments = [1.0, 0.5, 0.25]\n";
  const Scenario with_layer = load_scenario(f.dir.write("layer.toml", layer));
  ASSERT_TRUE(with_layer.haze.layer.has_value());
  EXPECT_DOUBLE_EQ(with_layer.haze.layer->optical_depth, 2.0);
  std::string text =
      f.text() + aerosol + layer + preetham_text +
      landsim::testing::read_file(source_file("scenes/examples/default.toml")) +
      landsim::testing::read_file(source_file("scenes/examples/kagwene_cameras.toml")) + cameras +
      sensor + iso;
  // RAMI's canopies (docs/CANOPIES.md): the periodic cell, the flat soil, the sun alone; each
  // shipped scenario loads.
  std::string rami;
  for (const char* scene : {"het01", "het04", "het06"}) {
    const auto path = source_file(std::string("scenes/rami/") + scene + ".toml");
    EXPECT_FALSE(load_scenario(path).canopies.empty()) << scene;
    rami += landsim::testing::read_file(path);
  }
  text += rami;
  // DISORT's plane-parallel cases (docs/VALIDATION.md): the layer, the uniform sky of case 11a.
  for (const char* scene : {"case_3a", "case_11a"}) {
    const auto path = source_file(std::string("scenes/disort/") + scene + ".toml");
    EXPECT_TRUE(load_scenario(path).haze.layer.has_value()) << scene;
    text += landsim::testing::read_file(path);
  }
  // The one atmosphere (docs/ATMOSPHERE.md "One atmosphere"): the shipped RAMI4ATM cases and
  // example, and the keys they leave at their defaults.
  for (const char* scene :
       {"scenes/rami4atm/hom00_whi_s00s_m04.toml", "scenes/rami4atm/hom00_bla_sd2s_m03.toml",
        "scenes/rami4atm/hom00_lam_ec2s_m04.toml", "scenes/rami4atm/hom00_bla_a00s_m04.toml",
        "scenes/examples/one_atmosphere.toml"}) {
    EXPECT_TRUE(load_scenario(source_file(scene)).haze.column.has_value()) << scene;
    text += landsim::testing::read_file(source_file(scene));
  }
  // RAMI4ATM's RPV and Ross-Li cases (docs/VALIDATION.md): each loads with the surface its
  // name says, on the terrain (a cell's soil) and every other material but water.
  int surfaces = 0;
  for (const auto& entry : std::filesystem::directory_iterator(source_file("scenes/rami4atm"))) {
    const std::string name = entry.path().stem().string();
    const bool rpv = name.find("_rpv_") != std::string::npos;
    if (!rpv && name.find("_rli_") == std::string::npos) continue;
    const Scenario r = load_scenario(entry.path());
    EXPECT_EQ(r.ground.brdf[0].model,
              rpv ? renderer::GroundBrdf::Model::rpv : renderer::GroundBrdf::Model::ross_li)
        << name;
    EXPECT_EQ(r.ground.brdf[8].model, r.ground.brdf[0].model) << name;
    if (rpv) {
      EXPECT_FLOAT_EQ(r.ground.brdf[0].k, 0.95f) << name;
    }
    EXPECT_FALSE(r.ground.brdf_white_sky[0]) << name;  // the albedo is rho_0 or f_iso
    ++surfaces;
  }
  EXPECT_EQ(surfaces, 18);
  const std::string column = terrain + views +
                             "[atmosphere]\nozone_column = 300\n[atmosphere.aerosol]\n"
                             "optical_depth = 0.1\ntype = \"continental-average\"\n"
                             "profile = \"uniform\"\nbottom = 100\ntop = 1500\n";
  const Scenario with_column = load_scenario(f.dir.write("column.toml", column));
  EXPECT_EQ(with_column.haze.column->ozone_column, 300.0);
  EXPECT_EQ(with_column.haze.uniform_bottom, 100.0);
  text += column;
  // Detection sets (docs/OBJECTS.md, SCENARIO.md [randomise]): objects placed by a view, in
  // copies, and a randomised set; the shipped example, and the keys it writes inline.
  const auto detection = source_file("scenes/examples/detection_set.toml");
  EXPECT_TRUE(load_scenario(detection).randomise.has_value());
  text += landsim::testing::read_file(detection);
  const std::string placed =
      "[[views]]\nname = \"v\"\nposition = [0.0, 0.0, 300.0]\ntarget = [300.0, 400.0, 150.0]\n"
      "[[objects]]\nname = \"p\"\nfile = \"" +
      source_file("data/objects/person.obj").string() +
      "\"\ncount = 2\nheading = \"random\"\n[objects.place]\nview = \"v\"\n"
      "range = [100, 400]\nbearing = [-20, 20]\nmin_visible = 0.3\ntrees = false\nseed = 4\n"
      "[randomise]\nimages = 2\nseed = 3\n"
      "[[views]]\nname = \"crop\"\nposition = [0.0, 0.0, 300.0]\ntarget = [300.0, 400.0, 150.0]\n"
      "focal_length = 200\npixel_pitch = 3.76\nsensor_pixels = [9576, 6388]\n"
      "region_centre = [7000, 1500]\n";
  const Scenario with_placed = load_scenario(
      f.dir.write("placed.toml", "[terrain]\nelevation = \"" +
                                     source_file("data/terrain/volcano.asc").string() +
                                     "\"\n[sun]\nelevation = 30\nazimuth = 100\n" + placed));
  ASSERT_EQ(with_placed.objects.size(), 2u);
  EXPECT_EQ(with_placed.objects[1].siting->seed, 4u);
  text += placed;
  for (const std::string& k : documented) {
    EXPECT_NE(text.find("\n" + k + " ="), std::string::npos)
        << "documented key '" << k << "' is set by no test scenario";
  }
}

TEST(FullScenario, SceneCarriesVegetationGrassAndGroundMaterials) {
  Fixture f;
  const Scenario s = load_scenario(f.dir.write("full.toml", f.text()));
  const renderer::Scene scene = build_scene(s);
  ASSERT_GT(scene.instances.size(), 10u);
  ASSERT_EQ(scene.bands.size(), 2u);
  EXPECT_FLOAT_EQ(scene.bands[0].weight[19], 10.0f);  // 760-780 nm: 770-900's first 10 nm
  EXPECT_FLOAT_EQ(scene.bands[0].weight[20], 20.0f);
  // The soil, moistened by 0.4: darker than the dry soil of its colour.
  EXPECT_LT(scene.ground.optics[4]->reflectance[14],
            0.9f * renderer::soil_optics(s.ground.soil, 0.0).reflectance[14]);
  for (const renderer::TreeInstance& t : scene.instances)
    ASSERT_LT(t.position.x + scene.origin.x, 200.0);  // columns 0-19
  // Grass exactly on the tiles whose cells have grass type 1 (columns 0-39, x < 400 m).
  const renderer::GrassCover& g = scene.grass;
  int grass = 0;
  for (int r = 0; r < g.rows; ++r) {
    for (int c = 0; c < g.cols; ++c) {
      const double x = g.corner.x + scene.origin.x + (c + 0.5) * g.tile;
      const double y = g.corner.y + scene.origin.y + (r + 0.5) * g.tile;
      const bool inside =
          x < 400.0 && x > 5.0 && x < 605.0 && y > 5.0 && y < 865.0;  // within the cell centres
      const std::uint8_t type = g.type[static_cast<std::size_t>(r) * g.cols + c];
      if (x >= 400.0) {
        ASSERT_EQ(type, 0) << x;
      }
      if (inside) {
        ASSERT_EQ(type, 1) << x << " " << y;
      }
      grass += type != 0;
    }
  }
  EXPECT_GT(grass, 1000);
  // Ground materials by column band: 1 road, 2 water, 3 rock, 4 soil, 5 under grass type 1.
  const auto material_at = [&](double x) {
    const terrain::GroundMesh& m = scene.ground.mesh;
    for (std::size_t t = 0; t < m.triangle_count(); ++t) {
      const Vec3 c = Vec3((m.vertices[m.indices[3 * t]] + m.vertices[m.indices[3 * t + 1]] +
                           m.vertices[m.indices[3 * t + 2]]) /
                          3.0f) +
                     scene.origin;
      if (std::abs(c.x - x) < 4.0 && std::abs(c.y - 400.0) < 6.0)
        return static_cast<int>(scene.ground.triangle_material[t]);
    }
    return -1;
  };
  EXPECT_EQ(material_at(100.0), 5);
  EXPECT_EQ(material_at(423.0), 4);
  EXPECT_EQ(material_at(473.0), 3);
  EXPECT_EQ(material_at(523.0), 2);
  EXPECT_EQ(material_at(573.0), 1);
  // West of the grid: the context terrain, which takes the albedo of the grid's edge.
  int west = 0;
  const terrain::GroundMesh& m = scene.ground.mesh;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    if (m.vertices[m.indices[3 * t]].x + scene.origin.x > -20.0) continue;
    ASSERT_EQ(scene.ground.material_id(t), renderer::Ground::kSurroundings);
    ++west;
  }
  EXPECT_GT(west, 20);
  EXPECT_EQ(scene.ground.material(renderer::Ground::kSurroundings).albedo,
            scene.ground.plain_albedo());
  EXPECT_TRUE(scene.ground.materials[1].water);
  ASSERT_FALSE(scene.prototypes.empty());
  EXPECT_NE(scene.prototypes[0].bark_texture, nullptr);
}

TEST(FullScenario, RefusesAMisplacedFeatureMapAndOrphanSpecies) {
  Fixture f;
  std::string shifted = f.text();
  shifted.replace(shifted.find("soil = "), 0, "origin = [90000.0, 0.0]\n");
  const Scenario s = load_scenario(f.dir.write("shifted.toml", shifted));
  try {
    build_scene(s);
    FAIL() << "a feature map off the terrain must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("does not overlap"), std::string::npos) << e.what();
  }
  std::string orphan = f.text();
  orphan.erase(orphan.find("[featuremaps]"),
               orphan.find("[[species]]") - orphan.find("[featuremaps]"));
  try {
    load_scenario(f.dir.write("orphan.toml", orphan));
    FAIL() << "species without feature maps must be refused";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[featuremaps]"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace landsim::scenes
