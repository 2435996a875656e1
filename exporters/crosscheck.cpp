#include "exporters/crosscheck.h"

#include <spdlog/spdlog.h>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <regex>
#include <stdexcept>

#include "core/atomic_file.h"
#include "core/input_error.h"
#include "exporters/pov_camera.h"
#include "exporters/pov_export.h"
#include "renderer/atmosphere/ground_level_sky.h"
#include "renderer/atmosphere/sky.h"
#include "renderer/output/exposure.h"
#include "renderer/output/image_output.h"
#include "renderer/transport/render.h"

namespace landsim::exporters {
namespace {

constexpr int kRegions = 4;  // per side, for the per-region luminance comparison

enum class Cover { sky, ground, tree, object };

// POV-Ray's own refusal of a scene: "File 'F' line N: Parse Error: message" in its log.
struct PovParseError : std::runtime_error {
  PovParseError(std::string in_file, int at_line, const std::string& message)
      : std::runtime_error(message), file(std::move(in_file)), line(at_line) {}
  std::string file;
  int line;
};

// The first parse error among POV-Ray's lines (its message continues on lines that start
// with a space), thrown; nothing when there is none.
void throw_parse_error(const std::vector<std::string>& lines) {
  static const std::regex kError(R"(File '([^']*)' line (\d+): Parse Error: (.*))");
  for (std::size_t i = 0; i < lines.size(); ++i) {
    std::smatch m;
    if (!std::regex_search(lines[i], m, kError)) continue;
    std::string message = m[3].str();
    for (std::size_t k = i + 1; k < lines.size() && !lines[k].empty() && lines[k][0] == ' '; ++k)
      message += lines[k];
    throw PovParseError(m[1].str(), std::stoi(m[2].str()), message);
  }
}

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

// Runs POV-Ray on `scene` from the directory `cwd` (where its includes are found), writing
// `output` (relative to cwd, or in /tmp: POV-Ray's default I/O restrictions allow no other
// place); returns seconds. Its output is appended to `log`; with `progress`, its "Rendered N
// of M pixels (P%)" lines are reported by tenths. Paths reach the shell as environment
// variables, so no file name can inject a command.
double run_povray(const std::filesystem::path& cwd, const std::filesystem::path& scene,
                  const std::string& output, const std::string& args, bool progress,
                  const std::filesystem::path& log) {
  const auto start = std::chrono::steady_clock::now();
  ::setenv("LS_POV_DIR", cwd.c_str(), 1);
  ::setenv("LS_POV_SCENE", scene.c_str(), 1);
  ::setenv("LS_POV_OUTPUT", output.c_str(), 1);
  // POV-Ray's own option parser takes names with spaces or semicolons only in double quotes.
  const std::string cmd =
      "cd \"$LS_POV_DIR\" && exec povray \"+I\\\"$LS_POV_SCENE\\\"\" "
      "\"+O\\\"$LS_POV_OUTPUT\\\"\" " +
      args + (progress ? " +V" : "") + " 2>&1";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run POV-Ray");
  std::ofstream log_file(log, std::ios::app);
  static const std::regex kPercent(R"(Rendered \d+ of \d+ pixels \((\d+)%\))");
  int reported = -1;
  std::string line;
  std::vector<std::string> lines;
  // POV-Ray rewrites its progress line with carriage returns: each is a line of its own.
  const auto finish_line = [&] {
    log_file << line << '\n';
    if (line.find("Parse Error") != std::string::npos ||
        (!lines.empty() && !line.empty() && line[0] == ' '))
      lines.push_back(line);
    std::smatch m;
    if (progress && std::regex_search(line, m, kPercent)) {
      const int percent = std::stoi(m[1].str());
      if (percent / 10 > reported / 10) spdlog::info("crosscheck: POV-Ray {}%", percent);
      reported = percent;
    }
    line.clear();
  };
  for (int c = std::fgetc(pipe); c != EOF; c = std::fgetc(pipe)) {
    if (c == '\r' || c == '\n') {
      finish_line();
    } else {
      line.push_back(static_cast<char>(c));
    }
  }
  if (!line.empty()) finish_line();
  if (::pclose(pipe) != 0) {
    throw_parse_error(lines);
    throw std::runtime_error("POV-Ray failed: see " + log.string());
  }
  return seconds_since(start);
}

renderer::FloatImage read_image(const std::filesystem::path& path) {
  renderer::FloatImage image;
  std::string error;
  if (!renderer::image_io().read(path.string(), false, image, error))
    throw std::runtime_error("cannot read " + path.string() + ": " + error);
  return image;
}

// The first three channels of pixel (x, y) (missing ones zero).
void pixel3(const renderer::FloatImage& image, int x, int y, float* out) {
  for (int c = 0; c < 3; ++c) out[c] = c < image.channels ? image.at(x, y, c) : 0.0f;
}

float luminance(const float* c) { return 0.2126f * c[0] + 0.7152f * c[1] + 0.0722f * c[2]; }

Cover ours(std::uint8_t object) {
  if (object == static_cast<std::uint8_t>(renderer::ObjectClass::object)) return Cover::object;
  if (object == static_cast<std::uint8_t>(renderer::ObjectClass::bark) ||
      object == static_cast<std::uint8_t>(renderer::ObjectClass::leaf)) {
    return Cover::tree;
  }
  // POV-Ray traces no ray outside a fisheye's circle either: black in its mask, as the sky.
  const bool nothing =
      object == 0 || object == static_cast<std::uint8_t>(renderer::ObjectClass::none);
  return nothing ? Cover::sky : Cover::ground;
}

Cover theirs(const float* rgb) {
  if (rgb[0] > 0.5f && rgb[1] > 0.5f) return Cover::object;  // yellow
  if (rgb[0] > 0.5f) return Cover::ground;
  if (rgb[1] > 0.5f || rgb[2] > 0.5f) return Cover::tree;
  return Cover::sky;
}

double iou(const std::vector<Cover>& a, const std::vector<Cover>& b, Cover c) {
  std::size_t both = 0, either = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    both += a[i] == c && b[i] == c;
    either += a[i] == c || b[i] == c;
  }
  return either == 0 ? 1.0 : static_cast<double>(both) / static_cast<double>(either);
}

// The sky's radiance at the horizon, averaged around it: POV-Ray's constant fog colour.
Vec3f horizon_mean(const renderer::SkyModel& sky) {
  Vec3f sum{};
  for (int i = 0; i < 64; ++i) {
    const float a = 2.0f * std::numbers::pi_v<float> * static_cast<float>(i) / 64.0f;
    sum += sky.radiance({std::cos(a), std::sin(a), 0.02f});
  }
  return sum / 64.0f;
}

// The heat map's scale: full red at this relative luminance difference.
constexpr float kHeatFullScale = 0.5f;
// Rows under the panels for the labels and the heat map's colour bar.
constexpr int kLegendRows = 34;

// landsim | POV-Ray (or the reference) | heat map, both renders at landsim's automatic exposure
// (the same gain, so their brightness compares), and under them the panels' names and the heat
// map's colour bar with its unit.
void write_side_by_side(const renderer::Film& film, const renderer::FloatImage& pov,
                        const std::vector<float>& heat, const std::string& other,
                        const std::filesystem::path& path) {
  const int w = film.width(), h = film.height();
  const int rows = h + kLegendRows;
  renderer::FloatImage out{3 * w, rows, 3,
                           std::vector<float>(9 * static_cast<std::size_t>(w) * rows)};
  const auto gain =
      static_cast<float>(renderer::preview_gain(renderer::exposure_ev100(film, std::nullopt)));
  const auto set = [&](int x, int y, const float* rgb) {
    std::copy(rgb, rgb + 3, out.pixels.begin() + 3 * (static_cast<std::ptrdiff_t>(y) * 3 * w + x));
  };
  float px[3];
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const Vec3f c = film.rgb(x, y) * gain;
      const float a[3] = {c.x, c.y, c.z};
      set(x, y, a);
      pixel3(pov, x, y, px);
      for (float& v : px) v *= gain;
      set(w + x, y, px);
      const float d = heat[static_cast<std::size_t>(y) * w + x];
      const float red[3] = {d, d * 0.1f, d * 0.1f};
      set(2 * w + x, y, red);
    }
  }
  // The colour bar: 0 at the left of the heat panel to kHeatFullScale (and beyond) at its right.
  for (int y = h + 4; y < h + 12; ++y)
    for (int x = 0; x < w; ++x) {
      const float d = (static_cast<float>(x) + 0.5f) / static_cast<float>(w);
      const float red[3] = {d, d * 0.1f, d * 0.1f};
      set(2 * w + x, y, red);
    }
  const std::vector<renderer::ImageLabel> labels = {
      {2, h + 28, "landsim"},
      {w + 2, h + 28, other},
      {2 * w + 2, h + 28, "0"},
      {2 * w + 24, h + 28, "|dL|/L"},
      {2 * w + std::max(80, w - 44), h + 28, fmt::format("{:.0f}%+", 100.0f * kHeatFullScale)}};
  AtomicFile file(path);
  std::string error, warning;
  if (!renderer::image_io().write_png(file.temp_path().string(), out, true, labels, error, warning))
    throw std::runtime_error("cannot write " + path.string() + ": " + error);
  file.commit();
}

}  // namespace

nlohmann::json camera_json(const std::optional<renderer::View>& camera) {
  if (!camera) return nullptr;
  const auto v = [](const Vec3& p) { return nlohmann::json::array({p.x, p.y, p.z}); };
  return {{"projection", renderer::projection_name(camera->lens.projection)},
          {"position", v(camera->position)},
          {"target", v(camera->target)},
          {"fov_y_deg", camera->fov_y_deg}};
}

namespace {

void write_reports(const CrosscheckReport& r, const CrosscheckOptions& o,
                   const std::filesystem::path& dir) {
  const nlohmann::json j = {
      {"object_iou", r.object_iou},
      {"tree_iou", r.tree_iou},
      {"ground_iou", r.ground_iou},
      {"scene_object_iou",
       r.scene_object_iou ? nlohmann::json(*r.scene_object_iou) : nlohmann::json()},
      {"luminance_mean_rel_diff", r.luminance_mean_rel_diff},
      {"luminance_region_max_rel_diff", r.luminance_region_max_rel_diff},
      {"landsim_seconds", r.landsim_seconds},
      {"povray_seconds", r.povray_seconds},
      {"thresholds",
       {{"min_iou", o.min_iou},
        {"max_mean_diff", o.max_mean_diff},
        {"max_region_diff", o.max_region_diff}}},
      {"coverage_measured", r.coverage_measured},
      {"shift", r.shift ? nlohmann::json(*r.shift) : nlohmann::json()},
      {"camera", camera_json(r.camera)},
      {"pass", r.pass}};
  write_file_atomically(dir / "report.json", j.dump(2) + "\n");
  write_file_atomically(
      dir / "report.html",
      fmt::format(
          "<!doctype html><meta charset=utf-8><title>landsim cross-check</title>\n"
          "<h1>landsim against POV-Ray: {}</h1>\n<img src=side_by_side.png alt='landsim | POV-Ray "
          "| "
          "difference'>\n"
          "<p>Left: landsim in its POV-comparable mode; middle: POV-Ray; both at landsim's "
          "automatic "
          "exposure. Right: the relative luminance difference |L_landsim - L_POV| / L_POV of "
          "pixels "
          "both see as objects, black 0 to full red at 50% and beyond (the bar below it).\n"
          "<table><tr><td>object IoU (mean of trees, ground{})<td>{:.4f} (min {})\n<tr><td>trees "
          "IoU<td>{:.4f}\n"
          "<tr><td>ground IoU<td>{:.4f}\n{}<tr><td>mean luminance difference<td>{:.2f}% (max "
          "{:.0f}%)\n"
          "<tr><td>largest region difference<td>{:.2f}% (max {:.0f}%)\n<tr><td>landsim<td>{:.2f} "
          "s\n"
          "<tr><td>POV-Ray<td>{:.2f} s\n{}</table>\n",
          r.pass ? "pass" : "FAIL", r.scene_object_iou ? ", scene objects" : "", r.object_iou,
          o.min_iou, r.tree_iou, r.ground_iou,
          r.scene_object_iou
              ? fmt::format("<tr><td>scene objects IoU<td>{:.4f}\n", *r.scene_object_iou)
              : std::string(),
          100 * r.luminance_mean_rel_diff, 100 * o.max_mean_diff,
          100 * r.luminance_region_max_rel_diff, 100 * o.max_region_diff, r.landsim_seconds,
          r.povray_seconds,
          r.camera
              ? fmt::format("<tr><td>camera read from {}<td>at ({:.2f}, {:.2f}, {:.2f}) looking at "
                            "({:.2f}, {:.2f}, {:.2f}), {:.2f} degrees high\n",
                            o.pov_scene.filename().string(), r.camera->position.x,
                            r.camera->position.y, r.camera->position.z, r.camera->target.x,
                            r.camera->target.y, r.camera->target.z, r.camera->fov_y_deg)
              : std::string()));
}

// The image at (x, y) shifted by (dx, dy) pixels: bilinear, edges clamped.
renderer::FloatImage shifted(const renderer::FloatImage& in, double dx, double dy) {
  renderer::FloatImage out = in;
  for (int y = 0; y < in.height; ++y)
    for (int x = 0; x < in.width; ++x) {
      const double sx = std::clamp(x - dx, 0.0, in.width - 1.0);
      const double sy = std::clamp(y - dy, 0.0, in.height - 1.0);
      const int x0 = static_cast<int>(sx), y0 = static_cast<int>(sy);
      const int x1 = std::min(x0 + 1, in.width - 1), y1 = std::min(y0 + 1, in.height - 1);
      const double tx = sx - x0, ty = sy - y0;
      for (int c = 0; c < in.channels; ++c)
        out.pixels[(static_cast<std::size_t>(y) * in.width + x) * in.channels + c] =
            static_cast<float>((in.at(x0, y0, c) * (1 - tx) + in.at(x1, y0, c) * tx) * (1 - ty) +
                               (in.at(x0, y1, c) * (1 - tx) + in.at(x1, y1, c) * tx) * ty);
    }
  return out;
}

// Mean relative luminance difference of `ref` over landsim's object pixels.
double misfit(const renderer::Film& film, const renderer::FloatImage& ref) {
  double sum = 0.0;
  std::size_t n = 0;
  float px[3];
  for (int y = 0; y < film.height(); ++y)
    for (int x = 0; x < film.width(); ++x) {
      if (film.object(x, y) == 0) continue;
      pixel3(ref, x, y, px);
      const double la = film.luminance(x, y);
      sum += std::abs(la - luminance(px)) / std::max(la, 1e-6);
      ++n;
    }
  return n > 0 ? sum / static_cast<double>(n) : 0.0;
}

// The translation of `ref` (whole pixels, then quarter pixels around the best) that fits
// landsim's render best, within `reach` pixels.
std::array<double, 2> best_shift(const renderer::Film& film, const renderer::FloatImage& ref,
                                 int reach) {
  std::array<double, 2> best{0.0, 0.0};
  double best_misfit = misfit(film, ref);
  const auto search = [&](double cx, double cy, double step, int steps) {
    for (int j = -steps; j <= steps; ++j)
      for (int i = -steps; i <= steps; ++i) {
        const double dx = cx + i * step, dy = cy + j * step;
        if (std::abs(dx) > reach || std::abs(dy) > reach) continue;
        const double m = misfit(film, shifted(ref, dx, dy));
        if (m < best_misfit - 1e-12) {
          best_misfit = m;
          best = {dx, dy};
        }
      }
  };
  search(0.0, 0.0, 1.0, reach);
  search(best[0], best[1], 0.25, 3);
  return best;
}

// The reference (and its mask) checked from their headers before anything renders: a
// garbage, huge or wrongly sized reference is refused before landsim.exr is written.
void check_reference(const CrosscheckOptions& o, const renderer::View& view) {
  for (const auto& [file, what] : {std::pair{o.reference, "reference"}, {o.mask, "mask"}}) {
    if (file.empty()) continue;
    int width = 0, height = 0, channels = 0;
    std::string error;
    if (!renderer::image_io().probe(file.string(), width, height, channels, error))
      throw InputError(fmt::format("{}: cannot read the {} image: {}", file.string(), what, error));
    if (width != view.width || height != view.height)
      throw InputError(fmt::format(
          "{}: the {} is {} x {} pixels, the view renders {} x {} (give the view that size, or "
          "--width/--height)",
          file.string(), what, width, height, view.width, view.height));
  }
}

// The user's reference image (and its mask, or its alpha) in landsim's units, the same size
// as the render (check_reference saw to that), translated by --align's search when asked.
void load_reference(const CrosscheckOptions& o, const renderer::Film& film, double exposure_gain,
                    renderer::FloatImage& ref, renderer::FloatImage& mask, CrosscheckReport& r) {
  renderer::FloatImage image;
  std::string error;
  if (!renderer::image_io().read(o.reference.string(), true, image, error))
    throw InputError(o.reference.string() + ": cannot read the reference image: " + error);
  // An integer image is display-referred: taken as an image at the export's exposure.
  if (image.display_referred)
    for (float& v : image.pixels) v = static_cast<float>(v / exposure_gain);
  if (!o.mask.empty()) {
    if (!renderer::image_io().read(o.mask.string(), false, mask, error))
      throw InputError(o.mask.string() + ": cannot read the mask: " + error);
  } else if (image.channels == 4) {
    // Alpha as coverage: objects (red, LS_Mask's ground colour) where it is over 0.5.
    mask = {image.width, image.height, 3, std::vector<float>(3 * image.pixels.size() / 4, 0.0f)};
    for (std::size_t i = 0; i < image.pixels.size() / 4; ++i)
      mask.pixels[3 * i] = image.pixels[4 * i + 3] > 0.5f ? 1.0f : 0.0f;
  } else {
    r.coverage_measured = false;
  }
  if (o.align > 0) {
    r.shift = best_shift(film, image, o.align);
    image = shifted(image, (*r.shift)[0], (*r.shift)[1]);
    if (r.coverage_measured) mask = shifted(mask, (*r.shift)[0], (*r.shift)[1]);
    spdlog::info("crosscheck: the reference fits best shifted by ({:.2f}, {:.2f}) pixels",
                 (*r.shift)[0], (*r.shift)[1]);
  }
  ref = std::move(image);
}

// Where POV-Ray runs: the directory it starts in, the scene file, and where its images go
// ("" : the run directory itself; else a directory under /tmp).
struct PovRun {
  std::filesystem::path cwd, scene, out, log;
};

// POV-Ray's colour image (EXR in cd/m2: LS_Exposure 1) with about `spp` samples (the nearest
// n x n antialiasing grid) and, with `mask`, its flat class colours (LS_Mask 1): pov.exr and
// mask.png in the run's output directory. Returns the colour render's seconds.
double render_with_povray(const PovRun& run, const renderer::View& view, int spp, bool mask) {
  spdlog::info("crosscheck: POV-Ray rendering (its log: {})", run.log.string());
  const int n = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(spp)))));
  const std::string size = fmt::format("+W{} +H{} -D -V", view.width, view.height);
  const auto output = [&](const char* name) {
    return run.out.empty() ? std::string(name) : (run.out / name).string();
  };
  const double seconds = run_povray(
      run.cwd, run.scene, output("pov.exr"),
      size + fmt::format(" +FE +A0.0 +AM1 +R{} Declare=LS_Mask=0 Declare=LS_Exposure=1", n), true,
      run.log);
  spdlog::info("crosscheck: POV-Ray done in {:.1f} s", seconds);
  if (mask) {
    spdlog::info("crosscheck: POV-Ray's class mask");
    run_povray(run.cwd, run.scene, output("mask.png"), size + " +FN -A Declare=LS_Mask=1", false,
               run.log);
  }
  return seconds;
}

// The user's own scene (--pov) rendered by POV-Ray from its own directory, its images moved
// into pov_dir. Its class mask only when the scene uses LS_Mask (as landsim's export does).
void render_user_scene(const CrosscheckOptions& o, const renderer::View& view,
                       const std::filesystem::path& pov_dir, renderer::FloatImage& pov,
                       renderer::FloatImage& mask, CrosscheckReport& r) {
  std::filesystem::create_directories(pov_dir);
  const std::filesystem::path file = std::filesystem::absolute(o.pov_scene);
  std::ifstream in(file);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const bool has_mask = text.find("LS_Mask") != std::string::npos;
  std::string tmp = "/tmp/landsim-pov-XXXXXX";
  if (::mkdtemp(tmp.data()) == nullptr) throw std::runtime_error("cannot make a directory in /tmp");
  const std::filesystem::path out = tmp;
  if (file.filename().string().find('"') != std::string::npos)
    throw InputError(file.string() + ": POV-Ray cannot read a file whose name has a double quote");
  const PovRun run{file.parent_path(), file.filename(), out, pov_dir / "povray.log"};
  try {
    r.povray_seconds = render_with_povray(run, view, o.spp, has_mask);
    for (const char* name : {"pov.exr", "mask.png"})
      if (std::filesystem::exists(out / name))
        std::filesystem::copy_file(out / name, pov_dir / name,
                                   std::filesystem::copy_options::overwrite_existing);
  } catch (const PovParseError& e) {
    std::filesystem::remove_all(out);
    // The user's scene (or a file it includes) is bad input: POV-Ray's words, its place.
    const std::filesystem::path where = (file.parent_path() / e.file).lexically_normal();
    throw InputError(fmt::format("{}:{}: POV-Ray: {}", where.string(), e.line, e.what()));
  } catch (...) {
    std::filesystem::remove_all(out);
    throw;
  }
  std::filesystem::remove_all(out);
  pov = read_image(pov_dir / "pov.exr");
  if (has_mask) {
    mask = read_image(pov_dir / "mask.png");
  } else {
    spdlog::warn("crosscheck: {} does not use LS_Mask: object coverage is not compared",
                 file.string());
    r.coverage_measured = false;
  }
}

}  // namespace

static CrosscheckReport run_crosscheck(const scenes::Scenario& scenario,
                                       const renderer::Scene& scene, const CrosscheckOptions& o) {
  (void)scenario;
  CrosscheckReport r;
  renderer::View view = scene.views.at(o.view);
  if (!o.pov_scene.empty()) {
    view = pov_camera_view(read_pov_camera(o.pov_scene, view.width, view.height), view);
    r.camera = view;
  }
  check_reference(o, view);
  const renderer::SkyModel sky(scene.sky, scene.sun, scene.ground.plain_albedo(),
                               scene.spectral_grid);
  PovExportOptions pov_options;
  pov_options.ambient_irradiance = sky.horizontal_irradiance();
  pov_options.fog_colour = horizon_mean(sky);
  pov_options.sky_zenith = sky.radiance({0.0f, 0.0f, 1.0f});
  pov_options.sky_horizon = pov_options.fog_colour;
  const std::filesystem::path pov_dir = o.out_dir / "pov";
  std::filesystem::create_directories(o.out_dir);
  if (o.reference.empty() && o.pov_scene.empty()) {
    renderer::View pov_view = view;
    pov_view.position += o.pov_camera_shift;
    pov_view.target += o.pov_camera_shift;
    export_pov(scene, pov_view, pov_dir, pov_options);
  }

  // landsim in the comparable mode, first sample at the pixel centre as POV-Ray samples.
  renderer::Scene comparable = scene;
  comparable.settings.spp = o.spp;
  // POV-Ray draws every tree at full detail: so does the comparable render.
  comparable.settings.degradation = false;
  // POV-Ray's ground is Lambertian (export_pov): so is the comparable render's.
  comparable.ground.brdf.fill({});
  renderer::RenderOptions ro;
  ro.threads = o.threads;
  ro.centre_first_sample = true;
  ro.comparable = renderer::ComparableLight{pov_options.ambient_irradiance, pov_options.fog_colour};
  spdlog::info("crosscheck: landsim (POV-comparable mode), {} x {}, {} spp", view.width,
               view.height, o.spp);
  ro.progress = [last = -1](double f) mutable {
    const int percent = static_cast<int>(f * 100.0);
    if (percent / 10 > last / 10) spdlog::info("crosscheck: landsim {}%", percent);
    last = percent;
  };
  auto start = std::chrono::steady_clock::now();
  const renderer::Film film = renderer::Renderer(comparable).render(view, ro);
  r.landsim_seconds = seconds_since(start);
  spdlog::info("crosscheck: landsim done in {:.1f} s", r.landsim_seconds);
  renderer::write_exr(film, o.out_dir / "landsim.exr", {{"mode", "POV-comparable"}});

  renderer::FloatImage pov, mask;
  if (!o.reference.empty()) {
    load_reference(o, film, pov_exposure_gain(scene, sky), pov, mask, r);
  } else if (!o.pov_scene.empty()) {
    render_user_scene(o, view, pov_dir, pov, mask, r);
  } else {
    PovRun run{pov_dir, "scene.pov", "", pov_dir / "povray.log"};
    r.povray_seconds = render_with_povray(run, view, o.spp, true);
    pov = read_image(pov_dir / "pov.exr");
    mask = read_image(pov_dir / "mask.png");
  }

  const int w = film.width(), h = film.height();
  std::vector<Cover> a(static_cast<std::size_t>(w) * h), b(a.size());
  std::vector<float> heat(a.size(), 0.0f);
  double sum_a = 0.0, sum_b = 0.0;
  std::vector<double> region_a(kRegions * kRegions, 0.0), region_b(region_a.size(), 0.0);
  std::vector<int> region_n(region_a.size(), 0);
  float px[3], mk[3];
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      a[i] = ours(film.object(x, y));
      if (r.coverage_measured) {
        pixel3(mask, x, y, mk);
        b[i] = theirs(mk);
      } else {
        b[i] = a[i];  // no mask: compare where landsim sees an object
      }
      if (a[i] == Cover::sky || b[i] == Cover::sky) continue;
      pixel3(pov, x, y, px);
      const double la = film.luminance(x, y), lb = luminance(px);
      sum_a += la;
      sum_b += lb;
      const std::size_t reg =
          static_cast<std::size_t>(y * kRegions / h * kRegions + x * kRegions / w);
      region_a[reg] += la;
      region_b[reg] += lb;
      ++region_n[reg];
      heat[i] = static_cast<float>(
          std::min(1.0, std::abs(la - lb) / std::max(lb, 1e-3) / kHeatFullScale));
    }
  }
  r.tree_iou = iou(a, b, Cover::tree);
  r.ground_iou = iou(a, b, Cover::ground);
  // Scene objects count as a third class when the scene has any.
  if (!scene.objects.empty()) {
    r.scene_object_iou = iou(a, b, Cover::object);
    r.object_iou = (r.tree_iou + r.ground_iou + *r.scene_object_iou) / 3.0;
  } else {
    r.object_iou = 0.5 * (r.tree_iou + r.ground_iou);
  }
  r.luminance_mean_rel_diff = sum_b > 0.0 ? std::abs(sum_a - sum_b) / sum_b : 1.0;
  const int min_pixels =
      std::max(1, w * h / (kRegions * kRegions * 10));  // regions at least 10% object
  for (std::size_t k = 0; k < region_a.size(); ++k) {
    if (region_n[k] < min_pixels || region_b[k] <= 0.0) continue;
    r.luminance_region_max_rel_diff = std::max(r.luminance_region_max_rel_diff,
                                               std::abs(region_a[k] - region_b[k]) / region_b[k]);
  }
  if (!r.coverage_measured) {
    r.object_iou = r.tree_iou = r.ground_iou = 0.0;
    r.scene_object_iou.reset();
  }
  r.pass = (!r.coverage_measured || r.object_iou >= o.min_iou) &&
           r.luminance_mean_rel_diff <= o.max_mean_diff &&
           r.luminance_region_max_rel_diff <= o.max_region_diff;
  write_side_by_side(film, pov, heat, o.reference.empty() ? "POV-Ray" : "reference",
                     o.out_dir / "side_by_side.png");
  write_reports(r, o, o.out_dir);
  return r;
}

CrosscheckReport crosscheck(const scenes::Scenario& scenario, const renderer::Scene& scene,
                            const CrosscheckOptions& o) {
  // Bad input found late (the user's POV-Ray scene, refused by POV-Ray) leaves nothing: the
  // folder if this run made it, else what this run writes in it.
  const bool fresh = !std::filesystem::exists(o.out_dir);
  try {
    // Under [atmosphere], its sun, sky and fog as seen from the ground: POV-Ray's lights, and
    // the comparable tracer's.
    return run_crosscheck(scenario, renderer::ground_level_equivalent(scene), o);
  } catch (const InputError&) {
    std::error_code ignored;
    if (fresh) {
      std::filesystem::remove_all(o.out_dir, ignored);
    } else {
      std::filesystem::remove(o.out_dir / "landsim.exr", ignored);
      std::filesystem::remove_all(o.out_dir / "pov", ignored);
    }
    throw;
  }
}

}  // namespace landsim::exporters
