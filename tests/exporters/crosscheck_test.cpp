// POV-Ray is installed by the project's set-up, so these tests run it: a small scene
// (terrain, a few trees, sun, haze) exports, renders in both renderers and passes; a moved
// camera fails; unsafe names are exported safely.
#include "exporters/crosscheck.h"

#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <regex>
#include <sstream>

#include "core/input_error.h"
#include "exporters/pov_export.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/output/image_io.h"
#include "renderer/output/image_output.h"
#include "renderer/transport/render.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/rasters.h"
#include "tests/support/temp_dir.h"
#include "tests/support/tools.h"

namespace landsim::exporters {
namespace {

using scenes::build_scene;
using scenes::load_scenario;
using scenes::Scenario;

using landsim::testing::source_file;
using landsim::testing::TempDir;

// The volcano's flat north with a 60 m x 60 m stand of trees (fan palms unless told) in view,
// sun and light haze.
const char* const kStandView =
    "[[views]]\nname = \"stand\"\nposition = [230.0, 700.0, 126.0]\ntarget = "
    "[230.0, 790.0, 104.0]\nfov = 45.0\nwidth = 96\nheight = 64\n";

Scenario small_scene(const TempDir& dir, const std::string& species = "fanpalm.xml",
                     const std::string& extra = "", const std::string& view = kStandView) {
  const std::string veg = (dir / "veg.tif").string();
  std::vector<double> cells(61 * 87, 0.0);
  for (int r = 5; r < 11; ++r)
    for (int c = 20; c < 26; ++c) cells[static_cast<std::size_t>(r) * 61 + c] = 1;  // bit 0
  const double gt[6] = {0.0, 10.0, 0.0, 870.0, 0.0, -10.0};
  landsim::testing::write_raster(veg, "GTiff", GDT_UInt16, 61, 87, cells, gt);
  const auto file = dir.write(
      "small.toml", "[terrain]\nelevation = \"" + source_file("data/terrain/volcano.asc").string() +
                        "\"\n"
                        "[featuremaps]\nvegetation = \"" +
                        veg +
                        "\"\n"
                        "[[species]]\nbit = 0\nfile = \"" +
                        source_file("data/species/" + species).string() +
                        "\"\n"
                        "variants = 1\ndensity_per_ha = 12\nmin_spacing = 5.0\n"
                        // Hosek-Wilkie's sky alone (its own aerosol): no [haze] beside it.
                        "[sun]\nelevation = 35.0\nazimuth = 250.0\n" +
                        view + extra);
  return load_scenario(file);
}

// Pixels of the first view whose object class is a tree (stem 2 or leaf 3) in landsim's
// render at full detail (as the comparison renders it).
int tree_pixels_in_view(const renderer::Scene& scene) {
  renderer::Scene full = scene;
  full.settings.degradation = false;
  const renderer::Film film = renderer::Renderer(full).render(full.views[0], {});
  int count = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x)
      count += film.object(x, y) == 2 || film.object(x, y) == 3;
  return count;
}

TEST(Crosscheck, SmallSceneAgreesWithPovRay) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const Scenario s = small_scene(dir);
  const renderer::Scene scene = build_scene(s);
  ASSERT_GE(scene.instances.size(), 2u);
  // The trees are in view (so the IoU below is not one of empty masks).
  const int tree_pixels = tree_pixels_in_view(scene);
  ASSERT_GT(tree_pixels, 20);
  CrosscheckOptions o;
  o.out_dir = dir / "check";
  o.spp = 1;
  const CrosscheckReport r = crosscheck(s, scene, o);
  EXPECT_GE(r.object_iou, 0.98);
  EXPECT_GT(r.tree_iou, 0.9);
  EXPECT_LE(r.luminance_mean_rel_diff, 0.05);
  EXPECT_TRUE(r.pass);
  for (const char* f : {"side_by_side.png", "report.json", "report.html", "landsim.exr",
                        "pov/scene.pov", "pov/meshes.inc"}) {
    EXPECT_TRUE(std::filesystem::exists(o.out_dir / f)) << f;
  }
}

TEST(Crosscheck, SceneObjectsAgreeWithPovRayAndJoinTheObjectIou) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const auto vehicle = [](const std::string& name, const std::string& file, double x, double y,
                          double heading) {
    return "[[objects]]\nname = \"" + name + "\"\nfile = \"" +
           source_file("data/objects/" + file).string() + "\"\nposition = [" + std::to_string(x) +
           ", " + std::to_string(y) + "]\nheading = " + std::to_string(heading) + "\n";
  };
  const Scenario s = small_scene(dir, "fanpalm.xml",
                                 vehicle("car", "car.obj", 222.0, 728.0, 40.0) +
                                     vehicle("truck", "truck.obj", 240.0, 745.0, -70.0));
  const renderer::Scene scene = build_scene(s);
  ASSERT_EQ(scene.objects.size(), 2u);
  CrosscheckOptions o;
  o.out_dir = dir / "check";
  o.spp = 1;
  const CrosscheckReport r = crosscheck(s, scene, o);
  ASSERT_TRUE(r.scene_object_iou);
  EXPECT_GT(*r.scene_object_iou, 0.9);
  EXPECT_NEAR(r.object_iou, (r.tree_iou + r.ground_iou + *r.scene_object_iou) / 3.0, 1e-12);
  EXPECT_TRUE(r.pass);
  // The vehicles are in view: the IoU above is not one of empty masks.
  const renderer::Film film = renderer::Renderer(scene).render(scene.views[0], {});
  int object_pixels = 0;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) object_pixels += film.target(x, y) != 0;
  EXPECT_GT(object_pixels, 60);
}

// Every camera model POV-Ray has, exported with its own camera block (docs/CAMERAS.md): a
// nadir view, a map of 1 m pixels and one of the whole grid (a pixel per cell), a rolled view,
// a fisheye and a panorama.
TEST(Crosscheck, NadirMapRolledFisheyeAndSphericalViewsAgreeWithPovRay) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  const std::pair<const char*, std::string> views[] = {
      {"nadir",
       "[[views]]\nname = \"nadir\"\nposition = [230.0, 785.0]\naltitude_above_ground = 120\n"
       "direction = [0, 0, -1]\nfov = 40\nwidth = 64\nheight = 64\n"},
      {"map",
       "[[views]]\nname = \"map\"\nprojection = \"orthographic\"\nposition = [230.0, 785.0, "
       "400.0]\npixel_size = 1.0\nwidth = 96\nheight = 64\n"},
      {"grid map", "[[views]]\nname = \"grid\"\nprojection = \"orthographic\"\nalign = \"grid\"\n"},
      {"rolled", std::string(kStandView) + "roll = 25\n"},
      {"fisheye",
       "[[views]]\nname = \"fisheye\"\nposition = [230.0, 735.0, 112.0]\ntarget = [230.0, "
       "790.0, 104.0]\nprojection = \"fisheye\"\nfov = 180\nwidth = 64\nheight = 64\n"},
      {"spherical",
       "[[views]]\nname = \"panorama\"\nposition = [230.0, 735.0, 112.0]\nyaw = 20\npitch = 0\n"
       "projection = \"spherical\"\nwidth = 128\nheight = 64\n"}};
  for (const auto& [name, view] : views) {
    TempDir dir;
    const Scenario s = small_scene(dir, "fanpalm.xml", "", view);
    const renderer::Scene scene = build_scene(s);
    // The trees are in view (the tree IoU means something), but for the whole grid's map:
    // its 10 m pixels see the ground between the palms' crowns.
    if (std::string(name) != "grid map") {
      EXPECT_GT(tree_pixels_in_view(scene), 8) << name;
    }
    CrosscheckOptions o;
    o.out_dir = dir / "check";
    o.spp = 1;
    const CrosscheckReport r = crosscheck(s, scene, o);
    EXPECT_GE(r.object_iou, 0.95) << name;
    EXPECT_GT(r.tree_iou, 0.85) << name;
    EXPECT_LE(r.luminance_mean_rel_diff, 0.05) << name;
    EXPECT_TRUE(r.pass) << name;
  }
}

// Another core's trees go through the same TreeGeometry, export and comparison.
CrosscheckReport crosscheck_species(const TempDir& dir, const std::string& species) {
  const Scenario s = small_scene(dir, species);
  const renderer::Scene scene = build_scene(s);
  EXPECT_GE(scene.instances.size(), 2u);
  EXPECT_GT(tree_pixels_in_view(scene), 20);  // in view: the tree IoU means something
  CrosscheckOptions o;
  o.out_dir = dir / "check";
  o.spp = 1;
  return crosscheck(s, scene, o);
}

void expect_agreement(const CrosscheckReport& r) {
  EXPECT_GT(r.tree_iou, 0.9);
  EXPECT_LE(r.luminance_mean_rel_diff, 0.05);
  EXPECT_TRUE(r.pass);
}

// A reference of the user's: POV-Ray's own images from an earlier run, landsim's render, the
// render shifted by two pixels, an 8-bit preview of it, an image of the wrong size.
TEST(Crosscheck, AReferenceImageComparesLikePovRayRunOnTheSpot) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const Scenario s = small_scene(dir);
  const renderer::Scene scene = build_scene(s);
  CrosscheckOptions o;
  o.out_dir = dir / "run";
  o.spp = 1;
  const CrosscheckReport live = crosscheck(s, scene, o);
  // POV-Ray's images of that run, given back: the same numbers.
  CrosscheckOptions ref = o;
  ref.out_dir = dir / "ref";
  ref.reference = dir / "run" / "pov" / "pov.exr";
  ref.mask = dir / "run" / "pov" / "mask.png";
  const CrosscheckReport again = crosscheck(s, scene, ref);
  EXPECT_EQ(again.object_iou, live.object_iou);
  EXPECT_EQ(again.luminance_mean_rel_diff, live.luminance_mean_rel_diff);
  EXPECT_EQ(again.luminance_region_max_rel_diff, live.luminance_region_max_rel_diff);
  // landsim's own render: identical, no coverage without a mask.
  ref.reference = dir / "run" / "landsim.exr";
  ref.mask.clear();
  const CrosscheckReport own = crosscheck(s, scene, ref);
  EXPECT_EQ(own.luminance_mean_rel_diff, 0.0);
  EXPECT_EQ(own.luminance_region_max_rel_diff, 0.0);
  EXPECT_FALSE(own.coverage_measured);
  EXPECT_TRUE(own.pass);
  // Shifted two pixels right: fails; --align finds the shift and passes.
  renderer::Film film = renderer::read_exr(dir / "run" / "landsim.exr");
  renderer::Film moved = film;
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      const int from = std::max(0, x - 2);
      for (int c = 0; c < 3; ++c)
        moved.rgb_data()[3 * (static_cast<std::size_t>(y) * film.width() + x) + c] =
            film.rgb_data()[3 * (static_cast<std::size_t>(y) * film.width() + from) + c];
    }
  renderer::write_exr(moved, dir / "moved.exr", {});
  ref.reference = dir / "moved.exr";
  ref.max_region_diff = 0.01;  // a regression check's tolerance
  const CrosscheckReport unaligned = crosscheck(s, scene, ref);
  EXPECT_FALSE(unaligned.pass) << unaligned.luminance_region_max_rel_diff;
  ref.align = 3;
  const CrosscheckReport aligned = crosscheck(s, scene, ref);
  ASSERT_TRUE(aligned.shift);
  EXPECT_NEAR((*aligned.shift)[0], -2.0, 0.26);
  EXPECT_NEAR((*aligned.shift)[1], 0.0, 0.26);
  EXPECT_TRUE(aligned.pass) << aligned.luminance_region_max_rel_diff;
  ref.align = 0;
  ref.max_region_diff = o.max_region_diff;
  // An 8-bit sRGB image of the render at the export's exposure: within the quantisation.
  const renderer::SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo(),
                               scene.spectral_grid);
  const auto gain = static_cast<float>(pov_exposure_gain(scene, sky));
  renderer::FloatImage png{film.width(), film.height(), 3, film.rgb_data()};
  for (float& v : png.pixels) v = std::min(1.0f, v * gain);
  std::string error, warning;
  ASSERT_TRUE(
      renderer::image_io().write_png((dir / "ref.png").string(), png, true, {}, error, warning))
      << error;
  ref.reference = dir / "ref.png";
  const CrosscheckReport eight = crosscheck(s, scene, ref);
  EXPECT_LT(eight.luminance_mean_rel_diff, 0.01);
  EXPECT_TRUE(eight.pass);
  // The wrong size: refused, both sizes named.
  png.width /= 2;
  png.pixels.resize(static_cast<std::size_t>(png.width) * png.height * 3);
  ASSERT_TRUE(
      renderer::image_io().write_png((dir / "small.png").string(), png, true, {}, error, warning));
  ref.reference = dir / "small.png";
  try {
    crosscheck(s, scene, ref);
    FAIL() << "a reference of the wrong size was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("48 x 64"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("96 x 64"), std::string::npos) << e.what();
  }
}

TEST(Crosscheck, SwayingAndLeaningTreesAgreeWithPovRay) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  // A strong wind: every tree swayed in its phase group and leaning by several degrees.
  const Scenario s =
      small_scene(dir, "fanpalm.xml", "[wind]\nspeed = 20.0\ngust = 10.0\ndirection = 90.0\n");
  const renderer::Scene scene = build_scene(s, 1.5);
  ASSERT_GE(scene.instances.size(), 2u);
  for (const renderer::TreeInstance& t : scene.instances) ASSERT_TRUE(t.leans());
  ASSERT_GT(tree_pixels_in_view(scene), 20);
  CrosscheckOptions o;
  o.out_dir = dir / "check";
  o.spp = 1;
  expect_agreement(crosscheck(s, scene, o));
}

TEST(Crosscheck, GraphPathsTreesAgreeWithPovRay) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  expect_agreement(crosscheck_species(dir, "graph_column.toml"));
}

TEST(Crosscheck, SelfOrganizingTreesAgreeWithPovRay) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  expect_agreement(crosscheck_species(dir, "so_envelope.toml"));
  // Leaves coloured by vigour are exported one mesh per vigour level, each in its colour.
  std::ifstream inc(dir / "check" / "pov" / "meshes.inc");
  const std::string text((std::istreambuf_iterator<char>(inc)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text.find("LS_Proto_0_4 "), std::string::npos);    // not as one mesh
  EXPECT_NE(text.find("LS_Proto_0_4_7 "), std::string::npos);  // full vigour
  EXPECT_NE(text.find("LS_Proto_0_4_5 "), std::string::npos);  // and weaker shoots
}

TEST(Crosscheck, HarmonicTreesAgreeWithPovRay) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  expect_agreement(crosscheck_species(dir, "harmonic_american_elm.toml"));
}

TEST(Crosscheck, MeasuredGrowthTreesAgreeWithPovRay) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  expect_agreement(crosscheck_species(dir, "london_plane.toml"));
}

TEST(Crosscheck, AMovedCameraFails) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const Scenario s = small_scene(dir);
  const renderer::Scene scene = build_scene(s);
  CrosscheckOptions o;
  o.out_dir = dir / "check";
  o.spp = 1;
  o.pov_camera_shift = {3.0, 0.0, 0.0};
  const CrosscheckReport r = crosscheck(s, scene, o);
  EXPECT_LT(r.object_iou, 0.98);
  EXPECT_FALSE(r.pass);
}

// A user's own POV-Ray scene: the stand seen from elsewhere (the export of a run whose POV-Ray
// camera was moved), its camera block rewritten as a user writes one. landsim at the
// scenario's view does not match POV-Ray's framing; landsim at the file's camera does.
TEST(Crosscheck, AUsersPovSceneIsComparedAtItsCamera) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const Scenario s = small_scene(dir);
  const renderer::Scene scene = build_scene(s);
  CrosscheckOptions o;
  o.out_dir = dir / "moved";
  o.spp = 1;
  o.pov_camera_shift = {6.0, -4.0, 2.0};
  const CrosscheckReport at_view = crosscheck(s, scene, o);
  EXPECT_LT(at_view.object_iou, 0.95);
  // The camera as a user writes it: POV-Ray's frame (y up), the aspect from the image size,
  // the horizontal angle.
  const renderer::View& v = scene.views[0];
  const Vec3 p = v.position + o.pov_camera_shift, t = v.target + o.pov_camera_shift;
  const double aspect = static_cast<double>(v.width) / v.height;
  const double angle = 2.0 * std::atan(std::tan(v.fov_y_deg * std::numbers::pi / 360.0) * aspect) *
                       180.0 / std::numbers::pi;
  std::string text = landsim::testing::read_file(o.out_dir / "pov" / "scene.pov");
  text = std::regex_replace(
      text, std::regex("camera \\{[^}]*\\}"),
      fmt::format("camera {{\n  location <{}, {}, {}>  // the stand, from the south-east\n"
                  "  right x*image_width/image_height\n  angle {}\n  look_at <{}, {}, {}>\n}}",
                  p.x, p.z, p.y, angle, t.x, t.z, t.y));
  const auto user = dir / "user" / "scene.pov";
  std::filesystem::create_directories(user.parent_path());
  std::ofstream(user) << text;
  std::filesystem::copy_file(o.out_dir / "pov" / "meshes.inc", dir / "user" / "meshes.inc");
  CrosscheckOptions mine = o;
  mine.out_dir = dir / "mine";
  mine.pov_camera_shift = {};
  mine.pov_scene = user;
  const CrosscheckReport r = crosscheck(s, scene, mine);
  ASSERT_TRUE(r.camera);
  EXPECT_NEAR(length(r.camera->position - p), 0.0, 1e-6);
  EXPECT_NEAR(r.camera->fov_y_deg, v.fov_y_deg, 1e-6);
  EXPECT_GE(r.object_iou, 0.98);
  EXPECT_GT(r.tree_iou, 0.9);
  EXPECT_TRUE(r.pass);
  EXPECT_TRUE(std::filesystem::exists(mine.out_dir / "pov" / "pov.exr"));
  EXPECT_FALSE(std::filesystem::exists(mine.out_dir / "pov" / "scene.pov"));  // not exported
}

// A scene of the user's own making, without LS_Mask, in a directory whose name a shell would
// misread: POV-Ray renders it there, coverage is not compared.
TEST(Crosscheck, AUsersSceneWithoutAMaskComparesLuminanceOnly) {
  LANDSIM_REQUIRE_TOOL("povray", "povray");
  TempDir dir;
  const Scenario s = small_scene(dir);
  const renderer::Scene scene = build_scene(s);
  const auto user = dir / "it's $HOME; a `dir`" / "my hill; 2.pov";
  std::filesystem::create_directories(user.parent_path());
  const renderer::View& v = scene.views[0];
  std::ofstream(user) << fmt::format(
      "#version 3.7;\nglobal_settings {{ assumed_gamma 1.0 }}\n#include \"ground.inc\"\n"
      "camera {{ location <{}, {}, {}> look_at <{}, {}, {}> right x*1.5 angle 60 }}\n"
      "light_source {{ <0, 1e6, 0> color rgb 3000 parallel point_at 0 }}\n",
      v.position.x, v.position.z, v.position.y, v.target.x, v.target.z, v.target.y);
  std::ofstream(user.parent_path() / "ground.inc")
      << "plane { y, -30 pigment { rgb 0.3 } finish { diffuse 1 } }\n";
  CrosscheckOptions o;
  o.out_dir = dir / "check";
  o.spp = 1;
  o.pov_scene = user;
  const CrosscheckReport r = crosscheck(s, scene, o);
  EXPECT_FALSE(r.coverage_measured);
  EXPECT_EQ(r.object_iou, 0.0);
  EXPECT_GT(r.povray_seconds, 0.0);
  const renderer::FloatImage pov = [&] {
    renderer::FloatImage image;
    std::string error;
    EXPECT_TRUE(
        renderer::image_io().read((o.out_dir / "pov" / "pov.exr").string(), false, image, error))
        << error;
    return image;
  }();
  ASSERT_EQ(pov.width, 96);
  // The grey plane, lit from overhead, where the view looks down on it.
  EXPECT_GT(pov.at(48, 60, 1), 0.0f);
  EXPECT_FALSE(std::filesystem::exists(o.out_dir / "pov" / "mask.png"));
}

TEST(PovExport, UnsafeNamesCannotInjectDirectives) {
  EXPECT_EQ(sanitize_for_pov("a\"b#c\nd}e"), "a_b_c_d_e");
  TempDir dir;
  renderer::Scene scene;
  renderer::View view{"evil\"\n#declare X = 1;\n#fopen", {0, -10, 5}, {0, 0, 0}, 40.0, 8, 8};
  export_pov(scene, view, dir.path(), {});
  std::istringstream lines(landsim::testing::read_file(dir / "scene.pov"));
  for (std::string line; std::getline(lines, line);) {
    EXPECT_EQ(line.find("#declare X"), std::string::npos) << line;
    EXPECT_EQ(line.find("#fopen"), std::string::npos) << line;
  }
  EXPECT_NE(landsim::testing::read_file(dir / "scene.pov").find("evil___declare X _ 1___fopen"),
            std::string::npos);
}

}  // namespace
}  // namespace landsim::exporters
