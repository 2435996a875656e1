// Scene objects ([[objects]], docs/OBJECTS.md): placement on the ground, heading, scale,
// tilt, clear radius, materials, and bad input located at the scenario's entry.
#include "scenes/builder/detail/scene_objects.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>

#include "core/input_error.h"
#include "renderer/acceleration/ground_probe.h"
#include "renderer/materials/object_texture.h"
#include "renderer/output/image_io.h"
#include "scenes/builder/memory_estimate.h"
#include "scenes/builder/scene_builder.h"
#include "tests/support/rasters.h"
#include "tests/support/temp_dir.h"

namespace landsim::scenes {
namespace {

using testing::TempDir;

// A planar terrain, 40 x 40 cells of 5 m from (1000, 2000): z = 100 + 0.15 y' + 0.05 x'
// (x', y' from the south-west cell centre), so any triangulation of it is the plane itself.
constexpr double kSlopeX = 0.05, kSlopeY = 0.15;
double plane(double x, double y) { return 100.0 + kSlopeX * (x - 1002.5) + kSlopeY * (y - 2002.5); }

std::string slope_asc(const TempDir& dir, bool hole = false) {
  std::string text =
      "ncols 40\nnrows 40\nxllcorner 1000\nyllcorner 2000\ncellsize 5\nNODATA_value -9999\n";
  for (int r = 0; r < 40; ++r) {
    for (int c = 0; c < 40; ++c) {
      const bool nodata = hole && r >= 18 && r < 22 && c >= 18 && c < 22;
      const double x = 1002.5 + 5.0 * c, y = 2002.5 + 5.0 * (39 - r);
      text += nodata ? "-9999 " : std::to_string(plane(x, y)) + " ";
    }
    text += "\n";
  }
  return dir.write(hole ? "hole.asc" : "slope.asc", text).string();
}

std::string vehicle(const std::string& name) {
  return testing::source_file("data/objects/" + name).string();
}

std::string scenario(const std::string& terrain, const std::string& extra) {
  return "[terrain]\nelevation = \"" + terrain +
         "\"\n[sun]\nelevation = 40\nazimuth = 200\n"
         "[[views]]\nname = \"v\"\nposition = [1080.0, 2080.0, 120.0]\ntarget = [1095.0, 2095.0, "
         "115.0]\nwidth = 64\nheight = 48\n" +
         extra;
}

std::string object(const std::string& name, const std::string& file, double x, double y,
                   const std::string& extra = "") {
  return "[[objects]]\nname = \"" + name + "\"\nfile = \"" + file + "\"\nposition = [" +
         std::to_string(x) + ", " + std::to_string(y) + "]\n" + extra + "\n";
}

renderer::Scene build(const TempDir& dir, const std::string& text) {
  return build_scene(load_scenario(dir.write("s.toml", text)));
}

// The lowest clearance of an object's vertices over the plane (terrain coordinates).
double lowest_clearance(const renderer::Scene& scene, std::size_t k) {
  const renderer::ObjectInstance& o = scene.objects[k];
  double lowest = std::numeric_limits<double>::infinity();
  for (const Vec3f& v : scene.object_prototypes[o.prototype].vertices) {
    const Vec3 w = o.apply(v) + scene.origin;
    lowest = std::min(lowest, w.z - plane(w.x, w.y));
  }
  return lowest;
}

Vec3 column(const renderer::ObjectInstance& o, int c) {
  return {o.transform[3 * c], o.transform[3 * c + 1], o.transform[3 * c + 2]};
}

TEST(SceneObjects, AnUprightObjectIsLoweredUntilOneVertexTouchesTheGround) {
  TempDir dir;
  const renderer::Scene scene = build(
      dir, scenario(slope_asc(dir), object("car", vehicle("car.obj"), 1090, 2100, "heading = 30") +
                                        object("truck", vehicle("truck.obj"), 1100, 2090)));
  ASSERT_EQ(scene.objects.size(), 2u);
  for (std::size_t k = 0; k < 2; ++k) {
    EXPECT_NEAR(lowest_clearance(scene, k), 0.0, 0.01) << scene.objects[k].name;
    // Upright: the object's z axis stays vertical.
    const Vec3 up = normalize(column(scene.objects[k], 2));
    EXPECT_NEAR(up.z, 1.0, 1e-9);
  }
  // Placed where asked (the origin's horizontal position).
  EXPECT_NEAR(scene.objects[0].transform[9] + scene.origin.x, 1090.0, 1e-9);
  EXPECT_NEAR(scene.objects[0].transform[10] + scene.origin.y, 2100.0, 1e-9);
}

TEST(SceneObjects, AnAlignedObjectFollowsTheGroundsNormalAndTouchesIt) {
  TempDir dir;
  const renderer::Scene scene =
      build(dir, scenario(slope_asc(dir), object("car", vehicle("car.obj"), 1090, 2100,
                                                 "heading = 75\nalign_to_ground = true")));
  const Vec3 up = normalize(column(scene.objects[0], 2));
  const Vec3 n = normalize(Vec3{-kSlopeX, -kSlopeY, 1.0});
  EXPECT_NEAR(dot(up, n), 1.0, 1e-6);
  EXPECT_NEAR(lowest_clearance(scene, 0), 0.0, 0.01);
  // The heading survives the tilt: the front's horizontal direction is still 75 degrees
  // clockwise from north.
  const Vec3 front = column(scene.objects[0], 1);
  EXPECT_NEAR(std::atan2(front.x, front.y) * 180.0 / std::numbers::pi, 75.0, 0.5);
}

// A flat 20 m panel on a knoll (a Gaussian hill 20 m high, sigma 30 m): its corners lie on
// the flanks 2 m below the top, so lowered until a vertex touched, the knoll rose through
// its middle (3 of 18 pixels were visible). Now no point of it is below the drawn ground,
// and it touches it.
TEST(SceneObjects, APanelOnAKnollClearsTheGroundAndTouchesIt) {
  TempDir dir;
  std::string knoll =
      "ncols 40\nnrows 40\nxllcorner 1000\nyllcorner 2000\ncellsize 5\nNODATA_value -9999\n";
  for (int r = 0; r < 40; ++r) {
    for (int c = 0; c < 40; ++c) {
      const double x = 1002.5 + 5.0 * c - 1100.0, y = 2002.5 + 5.0 * (39 - r) - 2100.0;
      knoll += std::to_string(100.0 + 20.0 * std::exp(-(x * x + y * y) / (2 * 30.0 * 30.0))) + " ";
    }
    knoll += "\n";
  }
  const std::string terrain = dir.write("knoll.asc", knoll).string();
  // In the file's x-z plane (its y is up), 0.1 m thick in nothing: one quad.
  const std::string panel =
      dir.write("panel.obj", "v -10 0 -10\nv 10 0 -10\nv 10 0 10\nv -10 0 10\nf 1 2 3\nf 1 3 4\n")
          .string();
  const renderer::Scene scene = build(dir, scenario(terrain, object("p", panel, 1100, 2100)));
  ASSERT_EQ(scene.objects.size(), 1u);
  const renderer::GroundProbe probe(scene.ground.mesh);
  double lowest = std::numeric_limits<double>::infinity();
  for (int i = 0; i <= 40; ++i)
    for (int j = 0; j <= 40; ++j) {
      const Vec3 w = scene.objects[0].apply(Vec3f{-10.0f + 0.5f * static_cast<float>(i),
                                                  -10.0f + 0.5f * static_cast<float>(j), 0.0f});
      const std::optional<double> h = probe.height(w.x, w.y);
      ASSERT_TRUE(h.has_value());
      lowest = std::min(lowest, w.z - *h);
    }
  EXPECT_GT(lowest, -0.05) << "the knoll rises through the panel";
  EXPECT_LT(lowest, 0.1) << "the panel floats";
}

TEST(SceneObjects, HeadingTurnsTheFrontClockwiseFromNorthAndScaleSizesIt) {
  TempDir dir;
  const renderer::Scene scene = build(
      dir,
      scenario(slope_asc(dir),
               object("east", vehicle("car.obj"), 1090, 2100, "heading = 90\nscale = 2") +
                   object("north", vehicle("car.obj"), 1060, 2100, "unit_scale = 0.5\nscale = 3")));
  // The file's front (+z, glTF's convention) becomes +y in the object frame; heading 90
  // turns it east.
  const Vec3 east = column(scene.objects[0], 1);
  EXPECT_NEAR(east.x, 2.0, 1e-9);
  EXPECT_NEAR(east.y, 0.0, 1e-9);
  EXPECT_NEAR(length(column(scene.objects[0], 0)), 2.0, 1e-9);
  const Vec3 north = column(scene.objects[1], 1);
  EXPECT_NEAR(north.y, 1.5, 1e-9);
  // One file, one prototype.
  EXPECT_EQ(scene.object_prototypes.size(), 1u);
  // The car is 4.4 m long in its file: its front bumper is 2.2 m x scale ahead.
  float front = -1e9f;
  for (const Vec3f& v : scene.object_prototypes[0].vertices) front = std::max(front, v.y);
  EXPECT_NEAR(front, 2.2f, 1e-4f);
}

TEST(SceneObjects, AnExplicitHeightPlacesTheOriginThere) {
  TempDir dir;
  const renderer::Scene scene = build(
      dir, scenario(slope_asc(dir), "[[objects]]\nname = \"high\"\nfile = \"" + vehicle("car.obj") +
                                        "\"\nposition = [1090, 2100, 150.5]\n"));
  EXPECT_NEAR(scene.objects[0].transform[11] + scene.origin.z, 150.5, 1e-9);
}

std::string aspen_everywhere() {
  return "[[species]]\nbit = 0\nfile = \"" +
         testing::source_file("data/species/quaking_aspen.toml").string() +
         "\"\nvariants = 1\ndensity_per_ha = 300\ncover = \"everywhere\"\n";
}

TEST(SceneObjects, TheClearRadiusRemovesExactlyTheTrunksInsideIt) {
  TempDir dir;
  const std::string terrain = slope_asc(dir);
  const renderer::Scene bare = build(dir, scenario(terrain, aspen_everywhere()));
  const renderer::Scene cleared =
      build(dir, scenario(terrain, aspen_everywhere() + object("car", vehicle("car.obj"), 1100,
                                                               2100, "clear_radius = 12.5")));
  const Vec3 at = Vec3{1100.0, 2100.0, 0.0} - bare.origin;
  std::size_t inside = 0;
  std::vector<renderer::TreeInstance> kept;
  for (const renderer::TreeInstance& t : bare.instances) {
    if (std::hypot(t.position.x - at.x, t.position.y - at.y) < 12.5)
      ++inside;
    else
      kept.push_back(t);
  }
  ASSERT_GT(inside, 0u) << "the test needs trees near the object";
  ASSERT_EQ(cleared.instances.size(), kept.size());
  for (std::size_t i = 0; i < kept.size(); ++i) {
    EXPECT_EQ(cleared.instances[i].position.x, kept[i].position.x);
    EXPECT_EQ(cleared.instances[i].position.y, kept[i].position.y);
  }
  // Without clear_radius: the footprint's radius (the car's corner, about 2.4 m) plus 1 m.
  const renderer::Scene by_default = build(
      dir, scenario(terrain, aspen_everywhere() + object("car", vehicle("car.obj"), 1100, 2100)));
  const double radius = std::hypot(0.92, 2.2) + 1.0;
  std::size_t kept_default = 0;
  for (const renderer::TreeInstance& t : bare.instances)
    if (std::hypot(t.position.x - at.x, t.position.y - at.y) >= radius) ++kept_default;
  EXPECT_EQ(by_default.instances.size(), kept_default);
}

TEST(SceneObjects, MaterialsComeFromTheFileAndOverridesReplaceThemByName) {
  TempDir dir;
  const renderer::Scene scene = build(
      dir, scenario(slope_asc(dir),
                    object("plain", vehicle("car.obj"), 1090, 2100) +
                        object("green", vehicle("car.obj"), 1070, 2100,
                               "[[objects.material]]\nname = \"paint_red\"\nalbedo = [0.05, 0.2, "
                               "0.05]\nroughness = 0.9\nmetallic = 0.5")));
  const renderer::ObjectPrototype& p = scene.object_prototypes[0];
  const auto paint = static_cast<std::size_t>(
      std::find(p.material_names.begin(), p.material_names.end(), "paint_red") -
      p.material_names.begin());
  ASSERT_LT(paint, p.material_names.size());
  // The MTL: Kd 0.3 0.03 0.02, Ns 200 -> roughness (2 / 202)^(1/4).
  const renderer::ObjectMaterial& file = scene.objects[0].materials[paint];
  EXPECT_NEAR(file.base_colour.x, 0.3f, 1e-6f);
  EXPECT_NEAR(file.roughness, std::pow(2.0 / 202.0, 0.25), 1e-5);
  EXPECT_EQ(file.metallic, 0.0f);
  const renderer::ObjectMaterial& over = scene.objects[1].materials[paint];
  EXPECT_NEAR(over.base_colour.y, 0.2f, 1e-6f);
  EXPECT_NEAR(over.roughness, 0.9f, 1e-6f);
  EXPECT_NEAR(over.metallic, 0.5f, 1e-6f);
}

TEST(SceneObjects, AnMtlTextureIsReadBesideTheMeshAndSampledWithVUp) {
  TempDir dir;
  // A 2 x 2 grey texture: top row black, white; bottom row white, black.
  landsim::testing::write_raster((dir / "tex.png").string(), "PNG", GDT_Byte, 2, 2,
                                 {0, 255, 255, 0});
  dir.write("quad.mtl", "newmtl sign\nKd 1 1 1\nmap_Kd tex.png\n");
  dir.write("quad.obj",
            "mtllib quad.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\n"
            "vt 0 1\nusemtl sign\nf 1/1 2/2 3/3 4/4\n");
  const renderer::Scene scene =
      build(dir, scenario(slope_asc(dir), object("sign", (dir / "quad.obj").string(), 1090, 2100)));
  const renderer::ObjectMaterial& m =
      scene.objects[0].materials.at(scene.object_prototypes[0].triangle_material.at(0));
  ASSERT_TRUE(m.texture);
  // v = 0.75 is the image's top row (v counts up from the bottom).
  EXPECT_NEAR(m.texture->colour(0.25f, 0.75f).x, 0.0f, 1e-6f);
  EXPECT_NEAR(m.texture->colour(0.75f, 0.75f).x, 1.0f, 1e-6f);
  EXPECT_NEAR(m.texture->colour(0.25f, 0.25f).x, 1.0f, 1e-6f);
  ASSERT_EQ(scene.object_prototypes[0].uvs.size(), 2 * scene.object_prototypes[0].vertices.size());
  // A texture that cannot be read is refused at the object's file.
  dir.write("quad.mtl", "newmtl sign\nKd 1 1 1\nmap_Kd missing.png\n");
  try {
    build(dir, scenario(slope_asc(dir), object("sign", (dir / "quad.obj").string(), 1090, 2100)));
    FAIL() << "a missing texture was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("[objects[0]] file"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("missing.png"), std::string::npos) << e.what();
  }
}

TEST(SceneObjects, TheGltfAndTheObjOfOneMeshGiveTheSameTrianglesAndMaterials) {
  TempDir dir;
  const renderer::Scene scene =
      build(dir, scenario(slope_asc(dir), object("obj", vehicle("car.obj"), 1090, 2100) +
                                              object("gltf", vehicle("car.gltf"), 1070, 2100)));
  ASSERT_EQ(scene.object_prototypes.size(), 2u);
  const renderer::ObjectPrototype& a = scene.object_prototypes[0];
  const renderer::ObjectPrototype& b = scene.object_prototypes[1];
  EXPECT_EQ(a.triangle_count(), b.triangle_count());
  // Same triangles, each with its material's colour (orders may differ between importers).
  const auto triangles = [&](const renderer::Scene& s, std::size_t k) {
    const renderer::ObjectPrototype& p = s.object_prototypes[k];
    std::vector<std::array<float, 12>> out;
    for (std::size_t t = 0; t < p.triangle_count(); ++t) {
      std::array<float, 12> row{};
      for (int c = 0; c < 3; ++c) {
        const Vec3f& v = p.vertices[p.indices[3 * t + c]];
        row[3 * c] = v.x;
        row[3 * c + 1] = v.y;
        row[3 * c + 2] = v.z;
      }
      const renderer::ObjectMaterial& m = s.objects[k].materials[p.triangle_material[t]];
      row[9] = m.base_colour.x;
      row[10] = m.base_colour.y;
      row[11] = m.roughness;
      out.push_back(row);
    }
    std::sort(out.begin(), out.end());
    return out;
  };
  const auto ta = triangles(scene, 0), tb = triangles(scene, 1);
  ASSERT_EQ(ta.size(), tb.size());
  for (std::size_t i = 0; i < ta.size(); ++i)
    for (int c = 0; c < 12; ++c) ASSERT_NEAR(ta[i][c], tb[i][c], 1e-5f) << i << " " << c;
}

// The message of the InputError that building `text` throws ("" when none is).
std::string error_of(const TempDir& dir, const std::string& text) {
  try {
    build(dir, text);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(SceneObjects, BadMeshesAndPlacementsAreRefusedAtTheirEntry) {
  TempDir dir;
  const std::string terrain = slope_asc(dir);
  // A file that is no mesh at all.
  const std::string garbage = dir.write("garbage.ply", "this is not a mesh\n").string();
  std::string e = error_of(dir, scenario(terrain, object("x", garbage, 1090, 2100)));
  EXPECT_NE(e.find("s.toml:"), std::string::npos) << e;
  EXPECT_NE(e.find("[objects[0]] file: " + garbage + ": a .ply file begins with the line \"ply\""),
            std::string::npos)
      << e;
  const std::string text = dir.write("garbage.obj", "this is not a mesh\n").string();
  e = error_of(dir, scenario(terrain, object("x", text, 1090, 2100)));
  EXPECT_NE(e.find("[objects[0]] file: cannot read mesh"), std::string::npos) << e;
  // Found by mesh_fuzz (session 18): a .gltf that is not JSON went on to Assimp's other
  // readers, and its OpenGEX reader read past its buffer on this. Only landsim's formats are
  // read now, and each must carry its format's signature.
  const std::string opengex = dir.write("scene.gltf", "geometrynode{\n \"asse&J2").string();
  e = error_of(dir, scenario(terrain, object("x", opengex, 1090, 2100)));
  EXPECT_NE(e.find("a .gltf file is JSON and this one is not"), std::string::npos) << e;
  const std::string no_magic = dir.write("scene.glb", std::string(40, 'x')).string();
  e = error_of(dir, scenario(terrain, object("x", no_magic, 1090, 2100)));
  EXPECT_NE(e.find("a .glb file begins with the magic \"glTF\""), std::string::npos) << e;
  // Vertices and no face.
  const std::string points = dir.write("points.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n").string();
  e = error_of(dir, scenario(terrain, object("x", points, 1090, 2100)));
  EXPECT_NE(e.find("[objects[0]] file"), std::string::npos) << e;
  EXPECT_NE(e.find("no faces (expected triangles or polygons)"), std::string::npos) << e;
  EXPECT_EQ(e.find("Validation failed"), std::string::npos) << e;  // Assimp's own wording
  // A vertex that is not a number.
  const std::string nan = dir.write("nan.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"
                                    "property float y\nproperty float z\nelement face 1\nproperty "
                                    "list uchar int vertex_indices\nend_header\n0 0 0\nnan 1 0\n0 "
                                    "0 1\n3 0 1 2\n")
                              .string();
  e = error_of(dir, scenario(terrain, object("x", nan, 1090, 2100)));
  EXPECT_NE(e.find("[objects[0]] file"), std::string::npos) << e;
  EXPECT_NE(e.find("not a finite number"), std::string::npos) << e;
  // Off the terrain, and partly off it.
  e = error_of(dir, scenario(terrain, object("x", vehicle("car.obj"), 900, 2100)));
  EXPECT_NE(e.find("s.toml:"), std::string::npos) << e;
  EXPECT_NE(e.find("[objects[0]] position: the object at (900, 2100)"), std::string::npos) << e;
  // (the ground ends at the raster's edge, x = 1000: the outer cells are drawn to it)
  e = error_of(dir, scenario(terrain, object("x", vehicle("car.obj"), 1001, 2100, "heading = 90")));
  EXPECT_NE(e.find("outside the terrain"), std::string::npos) << e;
  // Over a nodata hole.
  e = error_of(dir, scenario(slope_asc(dir, true), object("x", vehicle("car.obj"), 1100, 2100)));
  EXPECT_NE(e.find("nodata hole"), std::string::npos) << e;
  // An override of a material the mesh does not have.
  e = error_of(dir, scenario(terrain, object("x", vehicle("car.obj"), 1090, 2100,
                                             "[[objects.material]]\nname = \"paint\"\n")));
  EXPECT_NE(e.find("has no material 'paint'"), std::string::npos) << e;
  EXPECT_NE(e.find("'paint_red'"), std::string::npos) << e;
}

// Bytes of a little-endian 32-bit number.
std::string u32(std::uint32_t v) {
  return {static_cast<char>(v & 0xff), static_cast<char>((v >> 8) & 0xff),
          static_cast<char>((v >> 16) & 0xff), static_cast<char>((v >> 24) & 0xff)};
}

// Sizes a file claims beyond what it holds are refused from its header, before anything is
// allocated (a GLB claiming a 2 GB chunk had 2.2 GB allocated and filled; a PLY claiming 2^31
// faces ended in std::bad_alloc), and a glTF buffer outside the model's folder is never read
// (it read /etc/passwd as vertex data, then said "has no faces").
TEST(SceneObjects, MeshFilesThatClaimMoreThanTheyHoldAreRefusedFromTheirHeader) {
  TempDir dir;
  const std::string terrain = slope_asc(dir);
  const auto refused = [&](const std::string& file, const std::string& content) {
    const std::string path = dir.write(file, content).string();
    return error_of(dir, scenario(terrain, object("x", path, 1090, 2100)));
  };
  std::string e = refused("huge.glb", "glTF" + u32(2) + u32(0x80000000u) + std::string(88, ' '));
  EXPECT_NE(e.find("[objects[0]] file"), std::string::npos) << e;
  EXPECT_NE(e.find("the GLB header declares 2147483648 bytes but the file holds 100"),
            std::string::npos)
      << e;
  e = refused("chunk.glb",
              "glTF" + u32(2) + u32(40) + u32(0x80000000u) + "JSON" + std::string(20, ' '));
  EXPECT_NE(e.find("a GLB chunk at byte 12 declares 2147483648 bytes"), std::string::npos) << e;
  e = refused("faces.ply",
              "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
              "property float y\nproperty float z\nelement face 2147483648\nproperty list "
              "uchar int vertex_indices\nend_header\n" +
                  std::string(36, '\0'));
  EXPECT_NE(e.find("declares 2147483648 face elements"), std::string::npos) << e;
  std::filesystem::create_directories(dir / "model");
  const std::string outside =
      R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "../../../../../../etc/passwd", "byteLength": 36}]})";
  e = refused("model/outside.gltf", outside);
  EXPECT_NE(
      e.find("buffers[0] uri \"../../../../../../etc/passwd\" points outside the model's folder"),
      std::string::npos)
      << e;
  dir.write("model/short.bin", std::string(12, '\0'));
  e = refused(
      "model/short.gltf",
      R"({"asset": {"version": "2.0"}, "buffers": [{"uri": "short.bin", "byteLength": 36000000}]})");
  EXPECT_NE(e.find("declares byteLength 36000000 but the file holds 12 bytes"), std::string::npos)
      << e;
  // Found by mesh_fuzz (session 18): a uri longer than a file name escaped as
  // std::filesystem's error (a crash) instead of being refused.
  e = refused("model/long.gltf", R"({"asset": {"version": "2.0"}, "buffers": [{"uri": ")" +
                                     std::string(5000, 'a') + R"(", "byteLength": 4}]})");
  EXPECT_NE(e.find("buffers[0] uri \"aaaa"), std::string::npos) << e;
  EXPECT_NE(e.find("is not a file beside the model"), std::string::npos) << e;
}

// Many corners at one position: Assimp's smooth normals compare every pair (a 30,000-triangle
// fan took 4.7 s, 100,000 zero-area faces on three vertices over 120 s). The fan is read with
// its normals, the zero-area faces are left out (a mesh of nothing else has no faces).
TEST(SceneObjects, FansAndZeroAreaFacesReadInLinearTime) {
  TempDir dir;
  const std::string terrain = slope_asc(dir);
  constexpr int kFan = 30000;
  std::string fan = "v 0 0 0\n";  // a disc in the file's x-z plane: its y is up
  for (int i = 0; i <= kFan; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kFan;
    fan += "v " + std::to_string(std::cos(a)) + " 0 " + std::to_string(std::sin(a)) + "\n";
  }
  for (int i = 0; i < kFan; ++i)
    fan += "f 1 " + std::to_string(i + 2) + " " + std::to_string(i + 3) + "\n";
  const renderer::Scene scene =
      build(dir, scenario(terrain, object("x", dir.write("fan.obj", fan).string(), 1090, 2100)));
  ASSERT_EQ(scene.object_prototypes.size(), 1u);
  const renderer::ObjectPrototype& p = scene.object_prototypes[0];
  EXPECT_EQ(p.triangle_count(), static_cast<std::size_t>(kFan));
  ASSERT_EQ(p.normals.size(), p.vertices.size());
  for (const Vec3f& n : p.normals) ASSERT_NEAR(std::abs(n.z), 1.0f, 1e-4f);  // the disc's
  std::string flat = "v 0 0 0\nv 1 0 0\nv 2 0 0\n";
  for (int i = 0; i < 100000; ++i) flat += "f 1 2 3\n";
  const std::string e = error_of(
      dir, scenario(terrain, object("x", dir.write("flat.obj", flat).string(), 1090, 2100)));
  EXPECT_NE(e.find("no faces of any area (its 100000 triangles are all of zero area"),
            std::string::npos)
      << e;
}

TEST(SceneObjects, BadEntriesAreRefusedWhenTheScenarioIsRead) {
  TempDir dir;
  const std::string terrain = slope_asc(dir);
  const auto error = [&](const std::string& text) {
    try {
      load_scenario(dir.write("s.toml", text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  std::string e = error(scenario(terrain, object("a", vehicle("car.obj"), 1090, 2100) +
                                              object("a", vehicle("truck.obj"), 1070, 2100)));
  EXPECT_NE(e.find("[objects[1]] name: the name 'a' is used by another object"), std::string::npos)
      << e;
  e = error(scenario(terrain, object("a", (dir / "missing.obj").string(), 1090, 2100)));
  EXPECT_NE(e.find("[objects[0]] file: file not found"), std::string::npos) << e;
  e = error(scenario(terrain, "[[objects]]\nname = \"a\"\nfile = \"" + vehicle("car.obj") +
                                  "\"\nposition = [1, 2, 3, 4]\n"));
  EXPECT_NE(e.find("[objects[0]] position: expected [x, y] or [x, y, z]"), std::string::npos) << e;
  e = error(scenario(terrain, object("a", vehicle("car.obj"), 1090, 2100, "scale = 0")));
  EXPECT_NE(e.find("[objects[0]] scale"), std::string::npos) << e;
  e = error(scenario(terrain, object("a", vehicle("car.obj"), 1090, 2100, "colour = 1")));
  EXPECT_NE(e.find("colour"), std::string::npos) << e;
  // Every message is located in the scenario.
  EXPECT_NE(e.find("s.toml:"), std::string::npos) << e;
}

TEST(SceneObjects, TheMemoryEstimateCountsEachMeshOnceAndHandsItToTheBuilder) {
  TempDir dir;
  const std::string terrain = slope_asc(dir);
  const auto estimate = [&](const std::string& extra, VariantCache* keep = nullptr) {
    const MemoryEstimate e =
        estimate_memory(load_scenario(dir.write("e.toml", scenario(terrain, extra))), keep);
    for (const MemoryPart& p : e.parts)
      if (p.id == "objects") return static_cast<double>(p.bytes);
    return 0.0;
  };
  EXPECT_EQ(estimate(""), 0.0);
  const double one = estimate(object("a", vehicle("truck.obj"), 1090, 2100));
  const double two = estimate(object("a", vehicle("truck.obj"), 1090, 2100) +
                              object("b", vehicle("truck.obj"), 1070, 2100));
  // The truck's triangles: their Embree scenes (twice) at about 100 bytes each, at least.
  TempDir other;
  const renderer::Scene scene =
      build(other, scenario(slope_asc(other), object("a", vehicle("truck.obj"), 1090, 2100)));
  const double triangles = static_cast<double>(scene.object_prototypes[0].triangle_count());
  EXPECT_GT(one, 2.0 * 90.0 * triangles);
  EXPECT_LT(one, 2.0 * 400.0 * triangles);
  // A second object of the same file adds only its instance.
  EXPECT_GT(two, one);
  EXPECT_LT(two - one, 2000.0);
  // A base-colour texture is counted from its header: a 1024 x 1024 image held as linear
  // RGB floats, 12.6 MB (before, not at all).
  renderer::FloatImage white{1024, 1024, 3, std::vector<float>(1024 * 1024 * 3, 1.0f)};
  std::string error, warning;
  ASSERT_TRUE(renderer::image_io().write_png((dir / "white.png").string(), white, false, {}, error,
                                             warning))
      << error;
  dir.write("textured.mtl", "newmtl skin\nKd 1 1 1\nmap_Kd white.png\n");
  const std::string textured =
      dir.write("textured.obj",
                "mtllib textured.mtl\nusemtl skin\nv 0 0 0\nv 1 0 0\nv 1 0 1\nvt 0 0\nvt 1 "
                "0\nvt 1 1\nf 1/1 2/2 3/3\n")
          .string();
  const double plain_texture = estimate(object("t", textured, 1090, 2100));
  EXPECT_GT(plain_texture, 1024.0 * 1024.0 * 3 * 4.0);
  // The meshes read are handed on.
  VariantCache keep;
  estimate(object("a", vehicle("truck.obj"), 1090, 2100), &keep);
  EXPECT_EQ(keep.meshes.count(vehicle("truck.obj")), 1u);
}

}  // namespace
}  // namespace landsim::scenes

namespace landsim::scenes {
namespace {

// The shipped classes (data/objects/, made by its scripts) read upright at their sizes: the
// height along z, the length along the front (y at heading 0), as PROVENANCE.md lists them.
TEST(SceneObjects, EveryShippedClassStandsUprightAtItsSize) {
  struct Size {
    const char* file;
    double height, length;
  };
  const Size sizes[] = {{"car.obj", 1.45, 4.40},    {"truck.obj", 3.20, 7.46},
                        {"suv.obj", 1.95, 4.85},    {"tracked.obj", 2.30, 8.50},
                        {"person.obj", 1.75, 0.29}, {"tent.obj", 1.20, 2.20},
                        {"cow.obj", 1.47, 2.63},    {"hut.obj", 3.60, 3.70}};
  TempDir dir;
  std::string objects;
  int k = 0;
  for (const Size& s : sizes)
    objects += object(std::string(s.file).substr(0, std::string(s.file).find('.')), vehicle(s.file),
                      1030.0 + 12.0 * (k % 4), 2040.0 + 15.0 * (k / 4)),
        ++k;
  const renderer::Scene scene = build(dir, scenario(slope_asc(dir), objects));
  ASSERT_EQ(scene.objects.size(), std::size(sizes));
  for (std::size_t i = 0; i < std::size(sizes); ++i) {
    const renderer::ObjectInstance& o = scene.objects[i];
    double z0 = 1e9, z1 = -1e9, y0 = 1e9, y1 = -1e9;
    for (const Vec3f& v : scene.object_prototypes[o.prototype].vertices) {
      const Vec3 w = o.apply(v);
      z0 = std::min(z0, w.z), z1 = std::max(z1, w.z);
      y0 = std::min(y0, w.y), y1 = std::max(y1, w.y);
    }
    EXPECT_NEAR(z1 - z0, sizes[i].height, 0.02) << sizes[i].file;  // upright on the slope
    EXPECT_NEAR(y1 - y0, sizes[i].length, 0.02) << sizes[i].file;
    EXPECT_NEAR(lowest_clearance(scene, i), 0.0, 0.01) << sizes[i].file;  // it stands
  }
}

}  // namespace
}  // namespace landsim::scenes
