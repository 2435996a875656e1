// Range degradation at forest scale (issue 16). Not a Google Benchmark: peak memory is a
// per-process figure, so each mode runs in a process of its own (bench/degradation.sh runs
// them side by side and compares).
//
//   degradation_bench forest --mode on|off [--blend on|off] [--trees N] [--near M --far M]
//                           [--width W --height H --spp S] [--seed K] [--trunks yes] --out F.exr
//     A forest of N trees (12 variants of 3 Weber & Penn species) spread over a 50-degree
//     sector from 100 m to 3 km in front of a camera 10 m above flat ground, hazy. Prints
//     one JSON line: Embree build seconds, render seconds, peak resident memory.
//   degradation_bench compare A.exr B.exr
//     Mean absolute luminance difference of A and B over 8 x 8 pixel blocks, as a fraction
//     of B's mean (blocks average out most of the sampling noise), and the difference of the
//     images' means as a fraction of B's.
//   degradation_bench flythrough [--frames 24]
//     A camera gliding towards a forest edge, from 150 m to 20 m: for every tree seen, its pixel
//     coverage (3 x 3 rays a pixel) in each frame degraded (with and without blending) over its
//     coverage at full detail; prints the largest frame-to-frame change of that ratio for both.
//   degradation_bench tree --mode on|off --r2 R
//     One tree framed closely at the detail of calibrated range R: the cost per ray of a level.
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "core/counter_rng.h"
#include "renderer/acceleration/embree_scene.h"
#include "renderer/acceleration/stochastic_lod.h"
#include "renderer/camera.h"
#include "renderer/output/image_output.h"
#include "renderer/transport/render.h"
#include "trees/species.h"

namespace {

using namespace landsim;

constexpr double kPi = 3.14159265358979323846;

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

double peak_rss_mb() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return static_cast<double>(u.ru_maxrss) / 1024.0;
}

renderer::TreePrototype prototype(const std::string& file, std::uint64_t seed, Vec3f leaf) {
  renderer::TreePrototype p;
  const trees::Species species =
      trees::load_species(std::string(LANDSIM_SOURCE_DIR) + "/data/species/" + file);
  trees::TreeOptions o;
  o.seed = seed;
  p.geometry = trees::generate(species, o).geometry;
  p.bark_albedo = species.colours.bark;
  p.leaf_reflectance = leaf;
  p.leaf_transmittance = leaf * 0.5f;
  p.degradation = trees::degradation_factors(1.0, trees::Season::summer, false);
  return p;
}

// Flat ground, 12 prototypes, sun, sky and haze.
renderer::Scene base_scene() {
  renderer::Scene s;
  const float half = 8000.0f;
  s.ground.mesh.vertices = {{-half, -half, 0}, {half, -half, 0}, {half, half, 0}, {-half, half, 0}};
  s.ground.mesh.normals.assign(4, Vec3f{0, 0, 1});
  s.ground.mesh.indices = {0, 1, 2, 0, 2, 3};
  s.ground.albedo = {0.12f, 0.14f, 0.07f};
  const char* files[] = {"quaking_aspen.toml", "black_tupelo.toml", "ca_black_oak.toml"};
  for (int k = 0; k < 12; ++k)
    s.prototypes.push_back(
        prototype(files[k % 3], static_cast<std::uint64_t>(k + 1),
                  Vec3f{0.08f, 0.16f, 0.04f} * (0.8f + 0.05f * static_cast<float>(k))));
  s.sun.direction = normalize(Vec3{-0.4, 0.6, 0.5});
  s.haze.enabled = true;
  s.haze.visibility = 20000.0;
  return s;
}

// `count` trees, uniformly by area over the sector of half-angle 25 degrees about +y
// between `near` and `far` metres from the origin.
void plant_forest(renderer::Scene& s, std::size_t count, double near, double far) {
  for (std::size_t i = 0; i < count; ++i) {
    const CounterRng r(7, i, 0);
    const double radius = std::sqrt(near * near + (far * far - near * near) * r.uniform(0));
    const double angle = (r.uniform(1) - 0.5) * 50.0 * kPi / 180.0;
    s.instances.push_back({static_cast<std::uint32_t>(i % s.prototypes.size()),
                           {radius * std::sin(angle), radius * std::cos(angle), 0.0},
                           2.0 * kPi * r.uniform(2),
                           0.85 + 0.3 * r.uniform(3)});
  }
}

std::string arg(int argc, char** argv, const char* name, const char* fallback) {
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], name) == 0) return argv[i + 1];
  return fallback;
}

int forest(int argc, char** argv) {
  const bool on = arg(argc, argv, "--mode", "on") == "on";
  renderer::Scene s = base_scene();
  plant_forest(s, std::stoul(arg(argc, argv, "--trees", "100000")),
               std::stod(arg(argc, argv, "--near", "100")),
               std::stod(arg(argc, argv, "--far", "3000")));
  // --trunks yes: every tree reduced to its trunk, to separate the crowns' cost.
  if (arg(argc, argv, "--trunks", "no") == "yes")
    for (auto& p : s.prototypes)
      for (std::size_t g = 1; g < trees::kGroupCount; ++g) p.geometry.groups[g] = {};
  s.settings.degradation = on;
  s.settings.degradation_blend = arg(argc, argv, "--blend", "on") == "on";
  s.settings.spp = std::stoi(arg(argc, argv, "--spp", "4"));
  s.settings.seed = std::stoull(arg(argc, argv, "--seed", "1"));
  s.settings.max_bounces = 2;
  const renderer::View view{"forest",
                            {0.0, 0.0, 10.0},
                            {0.0, 1000.0, 5.0},
                            40.0,
                            std::stoi(arg(argc, argv, "--width", "1920")),
                            std::stoi(arg(argc, argv, "--height", "1080"))};
  const auto start = std::chrono::steady_clock::now();
  const renderer::Renderer renderer(s);
  const double shared_build = seconds_since(start);
  renderer::RenderStats stats;
  const renderer::Film film = renderer.render(view, {}, &stats);
  renderer::write_exr(film, arg(argc, argv, "--out", "forest.exr"), {});
  std::printf(
      "{\"mode\":\"%s\",\"trees\":%zu,\"build_s\":%.3f,\"render_s\":%.3f,\"trace_s\":%.3f,"
      "\"peak_rss_mb\":%.1f,\"rays_per_s\":%.0f}\n",
      on ? "on" : "off", s.instances.size(), shared_build + stats.setup_seconds,
      shared_build + stats.seconds, stats.seconds - stats.setup_seconds, peak_rss_mb(),
      stats.rays_per_second());
  return 0;
}

// One tree framed closely, drawn at the detail of calibrated range --r2: the cost per ray of
// each level's primitives.
int tree(int argc, char** argv) {
  renderer::Scene s = base_scene();
  s.prototypes.resize(1);
  s.instances.push_back({0, {0.0, 0.0, 0.0}, 0.0, 1.0});
  s.settings.degradation = arg(argc, argv, "--mode", "on") == "on";
  s.settings.spp = 4;
  renderer::View v{"tree", {-30.0, -12.0, 7.0}, {0.0, 0.0, 7.0}, 35.0, 512, 512};
  v.detail_range_scale =
      std::stod(arg(argc, argv, "--r2", "100")) /
      trees::calibrated_range(length(v.target - v.position), v.height, v.fov_y_deg);
  renderer::RenderStats stats;
  const auto start = std::chrono::steady_clock::now();
  renderer::Renderer(s).render(v, {}, &stats);
  std::printf("{\"r2\":%s,\"seconds\":%.3f,\"trace_s\":%.3f,\"rays\":%llu}\n",
              arg(argc, argv, "--r2", "100").c_str(), seconds_since(start),
              stats.seconds - stats.setup_seconds, static_cast<unsigned long long>(stats.rays));
  return 0;
}

int compare(const char* a_path, const char* b_path) {
  const renderer::Film a = renderer::read_exr(a_path), b = renderer::read_exr(b_path);
  constexpr int kBlock = 8;
  double diff = 0.0, mean = 0.0, mean_a = 0.0;
  int blocks = 0;
  for (int by = 0; by + kBlock <= a.height(); by += kBlock)
    for (int bx = 0; bx + kBlock <= a.width(); bx += kBlock) {
      double la = 0.0, lb = 0.0;
      for (int y = by; y < by + kBlock; ++y)
        for (int x = bx; x < bx + kBlock; ++x) {
          la += a.luminance(x, y);
          lb += b.luminance(x, y);
        }
      diff += std::abs(la - lb);
      mean += lb;
      mean_a += la;
      ++blocks;
    }
  // Also the difference of the two images' means (a bias shows here; noise averages out).
  std::printf("{\"mean_abs_block_diff_fraction\":%.5f,\"mean_diff_fraction\":%.5f,\"blocks\":%d}\n",
              diff / mean, (mean_a - mean) / mean, blocks);
  return 0;
}

// Each tree's coverage in `view`, in pixels: 3 x 3 rays per pixel, each carrying its pixel's
// mask as the renderer's rays do.
std::map<std::int32_t, double> coverage(const renderer::Scene& scene, const renderer::View& view) {
  const renderer::EmbreeScene embree(scene, &view);
  const renderer::Camera camera(view);
  std::map<std::int32_t, double> c;
  for (int y = 0; y < view.height; ++y)
    for (int x = 0; x < view.width; ++x) {
      const std::uint32_t mask = renderer::pixel_ray_mask(
          static_cast<std::uint64_t>(y) * static_cast<std::uint64_t>(view.width) +
          static_cast<std::uint64_t>(x));
      for (int k = 0; k < 9; ++k) {
        const float dx = (0.5f + static_cast<float>(k % 3)) / 3.0f;
        const float dy = (0.5f + static_cast<float>(k / 3)) / 3.0f;
        const auto hit = embree.intersect(
            *camera.ray(static_cast<float>(x) + dx, static_cast<float>(y) + dy), 0.0f, 1e30f, mask);
        if (hit && hit->instance >= 0) c[hit->instance] += 1.0 / 9.0;
      }
    }
  return c;
}

int flythrough(int argc, char** argv) {
  const int frames = std::stoi(arg(argc, argv, "--frames", "24"));
  renderer::Scene s = base_scene();
  plant_forest(s, 3000, 150.0, 700.0);  // the edge 150 m ahead
  using Coverage = std::map<std::int32_t, double>;
  std::vector<Coverage> full(static_cast<std::size_t>(frames)), blend(full), snap(full);
  for (int k = 0; k < frames; ++k) {
    // Towards the edge (150 m ahead at first, 20 m at the end), 5.65 m per frame: the nearest
    // trees cross from full-detail leaves to discs (r2 from 280 down to 37).
    const double y = 5.65 * k;
    const renderer::View v{"fly", {0.0, y, 20.0}, {0.0, y + 500.0, 5.0}, 30.0, 480, 270};
    const auto f = static_cast<std::size_t>(k);
    for (int mode = 0; mode < 3; ++mode) {
      s.settings.degradation = mode > 0;
      s.settings.degradation_blend = mode == 1;
      (mode == 0 ? full : mode == 1 ? blend : snap)[f] = coverage(s, v);
    }
  }
  // Largest change from frame to frame of a tree's coverage relative to its full-detail
  // coverage (which takes out the motion), over trees of at least 20 pixels in both frames.
  const auto changes = [&](const std::vector<Coverage>& degraded) {
    std::vector<double> w;
    for (std::size_t k = 0; k + 1 < full.size(); ++k)
      for (const auto& [tree, n] : full[k]) {
        const auto next = full[k + 1].find(tree);
        if (n < 20.0 || next == full[k + 1].end() || next->second < 20.0) continue;
        const auto ratio = [&](std::size_t frame, double reference) {
          const auto d = degraded[frame].find(tree);
          return d == degraded[frame].end() ? 0.0 : d->second / reference;
        };
        w.push_back(std::abs(ratio(k + 1, next->second) - ratio(k, n)));
      }
    std::sort(w.begin(), w.end());
    return w;
  };
  const auto quantile = [](const std::vector<double>& v, double q) {
    return v.empty() ? 0.0 : v[static_cast<std::size_t>(q * static_cast<double>(v.size() - 1))];
  };
  const std::vector<double> b = changes(blend), n = changes(snap);
  std::printf(
      "{\"frames\":%d,\"tree_frames\":%zu,\"blended\":{\"largest\":%.4f,\"p99\":%.4f,"
      "\"p90\":%.4f,\"median\":%.4f},\"snapped\":{\"largest\":%.4f,\"p99\":%.4f,"
      "\"p90\":%.4f,\"median\":%.4f}}\n",
      frames, b.size(), quantile(b, 1.0), quantile(b, 0.99), quantile(b, 0.9), quantile(b, 0.5),
      quantile(n, 1.0), quantile(n, 0.99), quantile(n, 0.9), quantile(n, 0.5));
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string what = argc > 1 ? argv[1] : "";
  if (what == "forest") return forest(argc, argv);
  if (what == "compare" && argc == 4) return compare(argv[2], argv[3]);
  if (what == "flythrough") return flythrough(argc, argv);
  if (what == "tree") return tree(argc, argv);
  std::fprintf(stderr, "usage: degradation_bench forest|compare A B|flythrough [options]\n");
  return 2;
}
