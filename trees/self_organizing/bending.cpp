#include "trees/self_organizing/bending.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/input_error.h"
#include "params/table_reader.h"
#include "trees/self_organizing/plant.h"

namespace landsim::trees::self_organizing {
namespace {

constexpr int kMaxPrisms = 48;         // longer paths: runs of internodes form one prism
constexpr double kHandleWeight = 1e4;  // per square metre, against 1 per square radian
constexpr int kIterations = 60;

// v turned by the rotation vector w (Rodrigues).
Vec3 rotate(const Vec3& w, const Vec3& v) {
  const double a = length(w);
  if (a < 1e-15) return v + cross(w, v);
  const Vec3 k = w * (1.0 / a);
  return v * std::cos(a) + cross(k, v) * std::sin(a) + k * (dot(k, v) * (1.0 - std::cos(a)));
}

// The path's prisms: runs of internodes (at most kMaxPrisms runs), each ending where a handle
// is, so every handle constrains a prism's end.
struct Prisms {
  std::vector<std::size_t> end;   // per prism: one past its last internode (path index)
  std::vector<Vec3> start, span;  // rest: where it starts, and start to end
};

Prisms make_prisms(const Plant& plant, const BendPath& resolved) {
  const std::vector<std::uint32_t>& path = resolved.path;
  const std::size_t run = (path.size() + kMaxPrisms - 1) / kMaxPrisms;
  Prisms p;
  std::size_t first = 0;
  for (std::size_t k = 0; k < path.size(); ++k) {
    const bool handle = std::find(resolved.handles.begin(), resolved.handles.end(), path[k]) !=
                        resolved.handles.end();
    if (handle || k + 1 - first >= run || k + 1 == path.size()) {
      p.end.push_back(k + 1);
      p.start.push_back(plant[path[first]].base);
      p.span.push_back(plant[path[k]].tip - plant[path[first]].base);
      first = k + 1;
    }
  }
  return p;
}

// The unknowns per prism: a rotation vector (its turn from rest) and, when stretching, a
// length factor.
struct Pose {
  std::vector<Vec3> turn;
  std::vector<double> scale;
};

// The end of each prism under `pose`, from the fixed start of the first.
std::vector<Vec3> prism_ends(const Prisms& p, const Pose& pose) {
  std::vector<Vec3> ends(p.end.size());
  Vec3 at = p.start.front();
  for (std::size_t k = 0; k < ends.size(); ++k)
    ends[k] = at = at + rotate(pose.turn[k], p.span[k]) * pose.scale[k];
  return ends;
}

class Solver {
 public:
  Solver(const Prisms& prisms, std::vector<std::pair<std::size_t, Vec3>> targets, double stretch)
      : p_(prisms), targets_(std::move(targets)), stretch_(stretch) {
    const std::size_t m = p_.end.size();
    per_ = stretch_ > 0.0 ? 4 : 3;
    n_ = m * per_;
    pose_.turn.assign(m, Vec3{0, 0, 0});
    pose_.scale.assign(m, 1.0);
  }

  Pose solve() {
    double lambda = 1e-3;
    std::vector<double> r = residuals(pose_);
    double cost = dot_self(r);
    for (int it = 0; it < kIterations; ++it) {
      const std::vector<double> jac = jacobian(pose_, r);
      const std::size_t rows = r.size();
      std::vector<double> a(n_ * n_, 0.0), g(n_, 0.0);
      for (std::size_t i = 0; i < rows; ++i)
        for (std::size_t c = 0; c < n_; ++c) {
          const double jc = jac[i * n_ + c];
          if (jc == 0.0) continue;
          g[c] += jc * r[i];
          for (std::size_t d = 0; d < n_; ++d) a[c * n_ + d] += jc * jac[i * n_ + d];
        }
      bool improved = false;
      for (int tries = 0; tries < 8 && !improved; ++tries) {
        std::vector<double> m = a;
        for (std::size_t c = 0; c < n_; ++c) m[c * n_ + c] += lambda * (1.0 + a[c * n_ + c]);
        std::vector<double> step(g.size());
        for (std::size_t c = 0; c < n_; ++c) step[c] = -g[c];
        if (!cholesky_solve(m, step)) {
          lambda *= 10.0;
          continue;
        }
        const Pose trial = moved(pose_, step);
        const std::vector<double> tr = residuals(trial);
        const double tc = dot_self(tr);
        if (tc < cost) {
          pose_ = trial, r = tr, cost = tc, improved = true;
          lambda = std::max(lambda * 0.3, 1e-9);
        } else {
          lambda *= 10.0;
        }
      }
      if (!improved) break;
    }
    return pose_;
  }

 private:
  static double dot_self(const std::vector<double>& v) {
    double s = 0.0;
    for (double x : v) s += x * x;
    return s;
  }

  Pose moved(const Pose& pose, const std::vector<double>& step) const {
    Pose out = pose;
    for (std::size_t k = 0; k < out.turn.size(); ++k) {
      out.turn[k] = out.turn[k] + Vec3{step[k * per_], step[k * per_ + 1], step[k * per_ + 2]};
      if (per_ == 4) out.scale[k] = std::max(0.05, out.scale[k] + step[k * per_ + 3]);
    }
    return out;
  }

  // The joints' elastic energy (how much each prism's turn differs from the one before it,
  // the first's from its fixed parent), the handles' distances, and stretching's cost.
  std::vector<double> residuals(const Pose& pose) const {
    std::vector<double> r;
    for (std::size_t k = 0; k < pose.turn.size(); ++k) {
      const Vec3 d = pose.turn[k] - (k == 0 ? Vec3{0, 0, 0} : pose.turn[k - 1]);
      r.insert(r.end(), {d.x, d.y, d.z});
    }
    const std::vector<Vec3> ends = prism_ends(p_, pose);
    const double w = std::sqrt(kHandleWeight);
    for (const auto& [prism, target] : targets_) {
      const Vec3 d = (ends[prism] - target) * w;
      r.insert(r.end(), {d.x, d.y, d.z});
    }
    if (per_ == 4) {
      // stretch 1: scaling nearly free; toward 0: ever stiffer.
      const double w_s = std::sqrt((1.0 - stretch_) / stretch_ + 1e-3);
      for (double s : pose.scale) r.push_back(w_s * (s - 1.0));
    }
    return r;
  }

  // Forward differences (the handle terms are smooth; the rest linear).
  std::vector<double> jacobian(const Pose& pose, const std::vector<double>& r0) const {
    std::vector<double> jac(r0.size() * n_, 0.0);
    constexpr double h = 1e-7;
    for (std::size_t c = 0; c < n_; ++c) {
      std::vector<double> step(n_, 0.0);
      step[c] = h;
      const std::vector<double> r = residuals(moved(pose, step));
      for (std::size_t i = 0; i < r.size(); ++i) jac[i * n_ + c] = (r[i] - r0[i]) / h;
    }
    return jac;
  }

  // Solves m x = b in place (b becomes x) for symmetric positive definite m.
  bool cholesky_solve(std::vector<double>& m, std::vector<double>& b) const {
    const std::size_t n = n_;
    for (std::size_t j = 0; j < n; ++j) {
      double d = m[j * n + j];
      for (std::size_t k = 0; k < j; ++k) d -= m[j * n + k] * m[j * n + k];
      if (!(d > 0.0)) return false;
      m[j * n + j] = std::sqrt(d);
      for (std::size_t i = j + 1; i < n; ++i) {
        double s = m[i * n + j];
        for (std::size_t k = 0; k < j; ++k) s -= m[i * n + k] * m[j * n + k];
        m[i * n + j] = s / m[j * n + j];
      }
    }
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t k = 0; k < i; ++k) b[i] -= m[i * n + k] * b[k];
      b[i] /= m[i * n + i];
    }
    for (std::size_t i = n; i-- > 0;) {
      for (std::size_t k = i + 1; k < n; ++k) b[i] -= m[k * n + i] * b[k];
      b[i] /= m[i * n + i];
    }
    return true;
  }

  const Prisms& p_;
  std::vector<std::pair<std::size_t, Vec3>> targets_;
  double stretch_;
  std::size_t per_ = 3, n_ = 0;
  Pose pose_;
};

// Moves internode i rigidly: its base to `base`, turned by w (and, for a path internode in a
// stretched prism, its length times s).
void place(Internode& n, const Vec3& base, const Vec3& w, double s) {
  const Vec3 span = rotate(w, n.tip - n.base) * s;
  n.base = base;
  n.tip = base + span;
  n.direction = normalize(span);
  n.frame = rotate(w, n.frame);
  n.lateral_direction = rotate(w, n.lateral_direction);
}

// Everything grown from `first` on (dead or alive: an earlier step may bring it back), turned
// by w about `pivot` and moved by `shift`.
void carry(Plant& plant, std::uint32_t first, const Vec3& pivot, const Vec3& moved_pivot,
           const Vec3& w) {
  std::vector<std::uint32_t> stack{first};
  while (!stack.empty()) {
    const std::uint32_t k = stack.back();
    stack.pop_back();
    if (k == kNone) continue;
    Internode& n = plant[k];
    place(n, moved_pivot + rotate(w, n.base - pivot), w, 1.0);
    stack.push_back(n.main);
    stack.push_back(n.lateral);
  }
}

std::string format_point(const Vec3& p) {
  return "[" + params::format_number(p.x) + ", " + params::format_number(p.y) + ", " +
         params::format_number(p.z) + "]";
}

double segment_distance(const Internode& n, const Vec3& p) {
  const Vec3 d = n.tip - n.base;
  const double len2 = dot(d, d);
  const double t = len2 > 0.0 ? std::clamp(dot(p - n.base, d) / len2, 0.0, 1.0) : 0.0;
  return length(p - (n.base + d * t));
}

// Of the n internodes index(0), ..., index(n - 1), the living one whose tip is nearest p
// (ties to the first).
template <typename Index>
std::uint32_t nearest_tip(const Plant& plant, std::size_t n, Index index, const Vec3& p) {
  std::uint32_t best = kNone;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t k = index(i);
    const double d = length(plant[k].tip - p);
    if (plant[k].alive && d < nearest) nearest = d, best = k;
  }
  return best;
}

}  // namespace

std::uint32_t nearest_internode(const Plant& plant, const Vec3& p) {
  std::uint32_t best = kNone;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::uint32_t k = plant.size() > 1 ? 1 : 0; k < plant.size(); ++k) {
    if (!plant[k].alive) continue;
    const double d = segment_distance(plant[k], p);
    if (d < nearest) nearest = d, best = k;
  }
  return best;
}

BendPath bend_path(const Plant& plant, const Bend& b) {
  BendPath r;
  if (b.handles.empty() || plant.size() == 0) return r;
  const std::uint32_t end = nearest_tip(
      plant, plant.size(), [](std::size_t i) { return static_cast<std::uint32_t>(i); },
      b.handles.back().at);
  if (end == kNone) return r;
  std::vector<std::uint32_t> from_root;  // the way up from the seedling to E
  for (std::uint32_t k = end; k != kNone; k = plant[k].parent) from_root.push_back(k);
  std::reverse(from_root.begin(), from_root.end());
  std::size_t first = 0;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < from_root.size(); ++i) {
    const double d = segment_distance(plant[from_root[i]], b.from);
    if (d < nearest) nearest = d, first = i;
  }
  r.path.assign(from_root.begin() + static_cast<std::ptrdiff_t>(first), from_root.end());
  for (std::size_t h = 0; h + 1 < b.handles.size(); ++h)
    r.handles.push_back(nearest_tip(
        plant, r.path.size(), [&](std::size_t i) { return r.path[i]; }, b.handles[h].at));
  r.handles.push_back(end);
  return r;
}

void bend(Plant& plant, const Bend& b) {
  const BendPath resolved = bend_path(plant, b);
  const std::vector<std::uint32_t>& path = resolved.path;
  if (path.empty())
    throw InputError((b.where.empty() ? "bend" : b.where) + ": no internode near from = " +
                     format_point(b.from) + " with a tip near the last handle (the tree has " +
                     std::to_string(plant.size()) + " internodes)");
  const Prisms prisms = make_prisms(plant, resolved);
  std::vector<std::pair<std::size_t, Vec3>> targets;
  for (std::size_t h = 0; h < b.handles.size(); ++h) {
    const auto at = static_cast<std::size_t>(
        std::find(path.begin(), path.end(), resolved.handles[h]) - path.begin());
    const auto prism = static_cast<std::size_t>(
        std::upper_bound(prisms.end.begin(), prisms.end.end(), at) - prisms.end.begin());
    targets.emplace_back(prism, b.handles[h].target);
  }
  const Pose pose = Solver(prisms, targets, b.stretch).solve();
  // Each prism's internodes turn with it; whatever else grows from them is carried along.
  std::vector<Internode> rest;
  for (std::uint32_t k : path) rest.push_back(plant[k]);
  Vec3 at = prisms.start.front();
  std::size_t first = 0;
  for (std::size_t q = 0; q < prisms.end.size(); ++q) {
    for (std::size_t k = first; k < prisms.end[q]; ++k) {
      const Internode& was = rest[k];
      place(plant[path[k]], at, pose.turn[q], pose.scale[q]);
      const Vec3 tip = plant[path[k]].tip;
      const bool last = k + 1 == path.size();
      for (std::uint32_t child : {was.main, was.lateral})
        if (child != kNone && (last || child != path[k + 1]))
          carry(plant, child, was.tip, tip, pose.turn[q]);
      at = tip;
    }
    first = prisms.end[q];
  }
}

}  // namespace landsim::trees::self_organizing
