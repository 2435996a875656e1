#include "trees/weber_penn/parameters.h"

#include <cmath>
#include <functional>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "params/table_reader.h"

namespace landsim::trees::weber_penn {
namespace {

// One accepted parameter: its name, range, whether it must be integral, and where it goes.
struct Spec {
  std::string name;
  double min, max;
  bool integer;
  std::function<void(Parameters&, double)> set;
};

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

template <typename T>
std::function<void(Parameters&, double)> field(T Parameters::*member) {
  return [member](Parameters& p, double v) { p.*member = static_cast<T>(v); };
}

template <typename T>
std::function<void(Parameters&, double)> level_field(int n, T LevelParameters::*member) {
  return [n, member](Parameters& p, double v) {
    p.level[static_cast<std::size_t>(n)].*member = static_cast<T>(v);
  };
}

std::vector<Spec> make_specs() {
  std::vector<Spec> s = {
      {"Shape", 0, 8, true, field(&Parameters::shape)},
      {"BaseSize", 0, 1, false, field(&Parameters::base_size)},
      {"Scale", 1e-3, 200, false, field(&Parameters::scale)},
      {"ScaleV", 0, 200, false, field(&Parameters::scale_v)},
      {"ZScale", 1e-3, 10, false, field(&Parameters::z_scale)},
      {"ZScaleV", 0, 10, false, field(&Parameters::z_scale_v)},
      {"Levels", 1, 6, true, field(&Parameters::levels)},
      {"Ratio", 1e-6, 1, false, field(&Parameters::ratio)},
      {"RatioPower", -5, 5, false, field(&Parameters::ratio_power)},
      {"Lobes", 0, 32, true, field(&Parameters::lobes)},
      {"LobeDepth", 0, 1, false, field(&Parameters::lobe_depth)},
      {"Flare", -1, 10, false, field(&Parameters::flare)},
      {"0Scale", 1e-3, 10, false, field(&Parameters::trunk_scale)},
      {"0ScaleV", 0, 10, false, field(&Parameters::trunk_scale_v)},
      {"0BaseSplits", 0, 32, true, field(&Parameters::base_splits)},
      {"Leaves", -1000, 1000, true, field(&Parameters::leaves)},
      {"LeafScale", 1e-4, 10, false, field(&Parameters::leaf_scale)},
      {"LeafScaleX", 1e-3, 10, false, field(&Parameters::leaf_scale_x)},
      {"LeafQuality", 1e-3, 1, false, field(&Parameters::leaf_quality)},
      {"LeafStemLen", -100, 100, false, field(&Parameters::leaf_stem_len)},
      {"LeafBend", 0, 1, false, field(&Parameters::leaf_bend)},
      {"LeafDistrib", 0, 8, true, field(&Parameters::leaf_distrib)},
      {"AttractionUp", -10, 10, false, field(&Parameters::attraction_up)},
      {"PruneRatio", 0, 1, false, field(&Parameters::prune_ratio)},
      {"PruneWidth", 0, 10, false, field(&Parameters::prune_width)},
      {"PruneWidthPeak", 0, 1, false, field(&Parameters::prune_width_peak)},
      {"PrunePowerLow", 0, 10, false, field(&Parameters::prune_power_low)},
      {"PrunePowerHigh", 0, 10, false, field(&Parameters::prune_power_high)},
      {"Smooth", 0, 1, false, field(&Parameters::smooth)},
  };
  for (int n = 0; n < 4; ++n) {
    const std::string d = std::to_string(n);
    const std::vector<Spec> level = {
        {d + "DownAngle", -180, 180, false, level_field(n, &LevelParameters::down_angle)},
        {d + "DownAngleV", -180, 180, false, level_field(n, &LevelParameters::down_angle_v)},
        {d + "Rotate", -360, 360, false, level_field(n, &LevelParameters::rotate)},
        {d + "RotateV", -360, 360, false, level_field(n, &LevelParameters::rotate_v)},
        {d + "Branches", 0, n == 0 ? 50.0 : 1000.0, true,
         level_field(n, &LevelParameters::branches)},
        {d + "BranchDist", 0, 1, false, level_field(n, &LevelParameters::branch_dist)},
        {d + "Length", n == 0 ? 1e-3 : 0, 100, false, level_field(n, &LevelParameters::length)},
        {d + "LengthV", 0, 100, false, level_field(n, &LevelParameters::length_v)},
        {d + "Taper", 0, 2.9999, false, level_field(n, &LevelParameters::taper)},
        {d + "SegSplits", 0, 4, false, level_field(n, &LevelParameters::seg_splits)},
        {d + "SplitAngle", 0, 180, false, level_field(n, &LevelParameters::split_angle)},
        {d + "SplitAngleV", 0, 180, false, level_field(n, &LevelParameters::split_angle_v)},
        {d + "CurveRes", 1, 64, true, level_field(n, &LevelParameters::curve_res)},
        {d + "Curve", -3600, 3600, false, level_field(n, &LevelParameters::curve)},
        {d + "CurveBack", -3600, 3600, false, level_field(n, &LevelParameters::curve_back)},
        // Negative: helix of that angle; -90 would be a flat spiral of infinite radius.
        {d + "CurveV", -89.9, 3600, false, level_field(n, &LevelParameters::curve_v)},
    };
    s.insert(s.end(), level.begin(), level.end());
  }
  return s;
}

const std::vector<Spec>& specs() {
  static const std::vector<Spec> kSpecs = make_specs();
  return kSpecs;
}

[[noreturn]] void refuse(const RawParam& raw, const std::string& name, const std::string& what) {
  throw InputError(raw.where + ": parameter " + name + ": " + what);
}

void apply(Parameters& p, const Spec& spec, const RawParam& raw) {
  if (!raw.number) refuse(raw, spec.name, "expected a number, got \"" + raw.text + "\"");
  const double v = *raw.number;
  const std::string range = number_text(spec.min) + " to " + number_text(spec.max);
  if (spec.integer && v != std::floor(v))
    refuse(raw, spec.name, "expected an integer from " + range + ", got " + number_text(v));
  if (!(v >= spec.min && v <= spec.max)) {
    refuse(raw, spec.name,
           "expected " + std::string(spec.integer ? "an integer" : "a number") + " from " + range +
               ", got " + number_text(v));
  }
  spec.set(p, v);
}

// Expected clones a stem of this level becomes (splits at each segment, base splits).
double clone_factor(const Parameters& p, int level) {
  const LevelParameters& lp = p.at(level);
  double f = std::pow(1.0 + lp.seg_splits, std::max(0, lp.curve_res - 1));
  if (level == 0) f *= 1.0 + p.base_splits;
  return f;
}

}  // namespace

Parameters::Parameters() {
  level[0].down_angle = 0.0;
  level[0].rotate = 0.0;
  level[0].branches = 1;
  level[0].branch_dist = 0.0;
  level[0].length = 1.0;
  level[2].curve_res = 1;
  level[3].curve_res = 1;
  level[2].branches = 5;
  level[3].branches = 5;
}

SizeEstimate estimate_size(const Parameters& p) {
  SizeEstimate e;
  // Clones share their stem's children (the per-segment count is divided among them), so
  // children multiply with the number of stem families, not with every clone.
  double families = p.level[0].branches;
  double worst_factor = 1.0;
  for (int level = 0; level < p.levels; ++level) {
    if (level > 0) {
      families *= p.at(level).branches;
      if (p.at(level).branches > worst_factor) {
        worst_factor = p.at(level).branches;
        e.dominant = std::to_string(std::min(level, 3)) + "Branches";
      }
    }
    const double clones = clone_factor(p, level);
    if (clones > worst_factor) {
      worst_factor = clones;
      e.dominant = std::to_string(std::min(level, 3)) + "SegSplits";
    }
    e.stems += families * clones;
  }
  e.leaves = families * std::abs(p.leaves);
  if (e.dominant.empty()) e.dominant = "0Branches";
  return e;
}

Parameters parse_parameters(const ParamTable& table, const std::string& file) {
  Parameters p;
  for (const auto& [name, raw] : table) {
    if (name == "LeafShape") {
      if (!parse_leaf_shape(raw.text, p.leaf_shape)) {
        refuse(raw, name,
               "expected 0-7 or oval, triangle, oak, maple3, maple5, leaflets, palm, sphere, disc, "
               "discN; got \"" +
                   raw.text + "\"");
      }
      continue;
    }
    const Spec* spec = nullptr;
    for (const Spec& s : specs()) {
      if (s.name == name) spec = &s;
    }
    if (spec == nullptr)
      refuse(raw, name,
             "unknown Weber & Penn parameter" + params::did_you_mean(name, parameter_names()));
    apply(p, *spec, raw);
  }
  const SizeEstimate e = estimate_size(p);
  if (e.stems > kMaxStems) {
    throw InputError(file + ": parameters would make about " + number_text(e.stems) +
                     " stems (limit " + number_text(kMaxStems) + "); reduce " + e.dominant +
                     " or Levels");
  }
  if (e.leaves > kMaxLeaves) {
    throw InputError(file + ": parameters would make about " + number_text(e.leaves) +
                     " leaves (limit " + number_text(kMaxLeaves) + "); reduce Leaves or " +
                     e.dominant);
  }
  return p;
}

Parameters read_parameters(params::TableReader& root, const std::string& file) {
  ParamTable table;
  // Each parameter as a number, or as text (names such as "disc1", numbers in quotes).
  const auto take = [&](const std::string& name, const std::string& expected) {
    const toml::node* n = root.value(name, expected);
    if (n == nullptr) return;
    RawParam raw;
    raw.where = root.location(n);
    if (n->is_number()) {
      raw.number = n->value<double>();
      std::ostringstream t;
      t << *raw.number;
      raw.text = t.str();
    } else if (n->is_string()) {
      raw.text = *n->value<std::string>();
      raw.number = param_number(raw.text);
    } else {
      root.fail(name, "expected a number or a string, got " + params::type_name(*n));
    }
    table.emplace(name, raw);
  };
  take("LeafShape", "0-7 or a shape name");
  for (const Spec& s : specs())
    take(s.name, std::string(s.integer ? "an integer" : "a number") + " from " +
                     number_text(s.min) + " to " + number_text(s.max));
  return parse_parameters(table, file);
}

std::vector<std::string> parameter_names() {
  std::vector<std::string> names{"LeafShape"};
  for (const Spec& s : specs()) names.push_back(s.name);
  return names;
}

}  // namespace landsim::trees::weber_penn
