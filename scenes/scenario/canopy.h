#pragma once
// Abstract canopies (docs/CANOPIES.md): the leaf clouds of radiative-transfer benchmarks such
// as RAMI, where a canopy is made of flat discs rather than of botanical trees. A [[canopy]]
// table gives a cloud's discs (from a file, or generated in a shape with a leaf angle
// distribution), where its copies stand, its bi-Lambertian leaves and, for abstract trees, a
// trunk under it. The text forms of disc and position files are read here, each mistake named
// at its file:line.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/vec3.h"

namespace landsim::scenes {

// One leaf: a disc of `radius` at `centre` (relative to its cloud's origin) facing `normal`.
struct LeafDisc {
  Vec3f centre;
  float radius = 0.0f;
  Vec3f normal{0.0f, 0.0f, 1.0f};
};

// Where a generated cloud's discs are placed, uniformly in the volume. Spheres and ellipsoids
// are centred on the cloud's origin; cylinders, cones and boxes stand on it (base at z = 0).
enum class CloudShape { sphere, ellipsoid, cylinder, cone, box };

// How leaf normals are distributed. `uniform`: uniform over the upper hemisphere (the
// distribution of RAMI's "UNI" files, which are uniform in cos theta); the others are de
// Wit's (1965) densities over the inclination theta in [0, pi/2] as RAMI defines them,
// azimuths uniform: planophile 2/pi (1 + cos 2 theta), erectophile 2/pi (1 - cos 2 theta),
// plagiophile 2/pi (1 - cos 4 theta), extremophile 2/pi (1 + cos 4 theta).
enum class LeafAngles { uniform, planophile, erectophile, plagiophile, extremophile };

struct GeneratedCloud {
  CloudShape shape = CloudShape::sphere;
  // sphere: radius; ellipsoid: semi-axes x, y, z; cylinder and cone: base radius and height;
  // box: sides x, y, z. Metres.
  Vec3 size{1.0, 1.0, 1.0};
  int discs = 1000;
  double disc_radius = 0.05;
  LeafAngles angles = LeafAngles::uniform;
  int variants = 1;  // seeded clouds the copies are spread over
};

// A trunk: a vertical cylinder from the copy's position up to the cloud, which then stands
// on its top.
struct CanopyTrunk {
  double radius = 0.15;
  double height = 1.5;
  double reflectance = 0.14;
};

struct CanopySettings {
  std::string name;
  std::string location;         // file:line of the table, for messages
  std::vector<LeafDisc> discs;  // read from `leaves`, or empty when generated
  std::optional<GeneratedCloud> generated;
  std::vector<Vec3> positions;  // where each copy's origin goes, terrain coordinates
  // Where each position was given, for messages: `positions_file`:`position_lines[i]`.
  std::string positions_file;
  std::vector<std::uint32_t> position_lines;
  double reflectance = 0.5;  // the leaves', each side (bi-Lambertian)
  double transmittance = 0.4;
  std::optional<CanopyTrunk> trunk;
};

// Discs as `radius x y z nx ny nz` per line ('#' comments and blank lines skipped); the
// normals are made unit. Throws InputError naming `file`:line.
std::vector<LeafDisc> parse_leaf_discs(std::string_view text, const std::string& file);

// Positions as `x y z` per line, each one's line number in `lines` when given. Throws
// InputError naming `file`:line.
std::vector<Vec3> parse_positions(std::string_view text, const std::string& file,
                                  std::vector<std::uint32_t>* lines = nullptr);

// At most this many discs in one cloud, and copies of one canopy (RAMI's largest scene, HET06,
// has 10,000 trees of 6,480 discs).
inline constexpr int kMaxCloudDiscs = 10'000'000;
// A disc file's bounds, a generated cloud's (its disc_radius and size keys): a disc's radius,
// and how far its centre lies from the cloud's origin, metres.
inline constexpr double kMaxDiscRadius = 100.0;
inline constexpr double kMaxCloudReach = 1e4;
inline constexpr int kMaxCanopyCopies = 1'000'000;

}  // namespace landsim::scenes
