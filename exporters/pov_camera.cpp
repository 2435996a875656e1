#include "exporters/pov_camera.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <map>
#include <numbers>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include "core/input_error.h"

namespace landsim::exporters {
namespace {

struct Token {
  enum Kind { number, word, punct, string } kind;
  std::string text;
  double value = 0.0;
  int line = 0;
};

// POV-Ray's scene language, as far as finding and reading a camera block needs: numbers,
// words, strings, one-character punctuation; `//` and (nested) `/* */` comments skipped.
class Lexer {
 public:
  Lexer(const std::string& text, std::string name) : s_(text), name_(std::move(name)) {}

  std::vector<Token> tokens() {
    std::vector<Token> out;
    while (skip_space_and_comments()) out.push_back(next());
    return out;
  }

 private:
  bool skip_space_and_comments() {
    while (i_ < s_.size()) {
      if (s_[i_] == '\n') ++line_;
      if (std::isspace(static_cast<unsigned char>(s_[i_]))) {
        ++i_;
      } else if (s_.compare(i_, 2, "//") == 0) {
        while (i_ < s_.size() && s_[i_] != '\n') ++i_;
      } else if (s_.compare(i_, 2, "/*") == 0) {
        skip_block_comment();
      } else {
        return true;
      }
    }
    return false;
  }

  void skip_block_comment() {
    const int start = line_;
    int depth = 0;
    while (i_ < s_.size()) {
      if (s_.compare(i_, 2, "/*") == 0) {
        ++depth;
        i_ += 2;
      } else if (s_.compare(i_, 2, "*/") == 0) {
        i_ += 2;
        if (--depth == 0) return;
      } else {
        line_ += s_[i_++] == '\n';
      }
    }
    throw InputError(fmt::format("{}:{}: a /* comment is never closed", name_, start));
  }

  Token next() {
    const char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c)) ||
        (c == '.' && i_ + 1 < s_.size() && std::isdigit(static_cast<unsigned char>(s_[i_ + 1]))))
      return number();
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      const std::size_t start = i_;
      while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_'))
        ++i_;
      return {Token::word, s_.substr(start, i_ - start), 0.0, line_};
    }
    if (c == '"') return quoted();
    ++i_;
    return {Token::punct, std::string(1, c), 0.0, line_};
  }

  Token number() {
    const std::string text = s_.substr(i_, 64);
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(text.c_str(), &end);
    const auto used = static_cast<std::size_t>(end - text.c_str());
    // Underflow reads as (nearly) zero, as POV-Ray reads it; overflow is no number at all.
    if (errno == ERANGE && std::abs(v) > 1.0)
      throw InputError(fmt::format("{}:{}: the number {} is beyond a double's range", name_, line_,
                                   text.substr(0, used)));
    Token t{Token::number, text.substr(0, used), v, line_};
    i_ += std::max<std::size_t>(used, 1);
    return t;
  }

  Token quoted() {
    const int start = line_;
    for (++i_; i_ < s_.size() && s_[i_] != '"'; ++i_) {
      if (s_[i_] == '\\') ++i_;
      if (i_ < s_.size() && s_[i_] == '\n') ++line_;
    }
    if (i_ >= s_.size())
      throw InputError(fmt::format("{}:{}: a string is never closed", name_, start));
    ++i_;
    return {Token::string, "", 0.0, start};
  }

  const std::string& s_;
  std::string name_;
  std::size_t i_ = 0;
  int line_ = 1;
};

// A value of the scene language: a float or a vector.
struct Value {
  Vec3 v;
  bool vector = false;
};

Value scalar(double s) { return {{s, s, s}, false}; }

// Evaluates the expressions of a camera block's items.
class Evaluator {
 public:
  Evaluator(const std::vector<Token>& t, std::size_t begin, std::size_t end, std::string name,
            int width, int height)
      : t_(t), i_(begin), end_(end), name_(std::move(name)), width_(width), height_(height) {}

  bool done() const { return i_ >= end_; }
  const Token& peek() const { return t_[i_]; }
  const Token& take() { return t_[i_++]; }
  [[noreturn]] void fail(const Token& at, const std::string& what) const {
    throw InputError(fmt::format("{}:{}: camera: {}", name_, at.line, what));
  }

  Value expression() {
    Value a = term();
    while (!done() && (peek().text == "+" || peek().text == "-") && peek().kind == Token::punct) {
      const bool plus = take().text == "+";
      const Value b = term();
      a = {plus ? a.v + b.v : a.v - b.v, a.vector || b.vector};
    }
    return a;
  }

  // A float is promoted to a vector of three, as POV-Ray does.
  Vec3 vector_of() { return expression().v; }

  double float_of(const Token& item) {
    const Value v = expression();
    if (v.vector) fail(item, item.text + ": expected a number, found a vector");
    return v.v.x;
  }

 private:
  Value term() {
    Value a = unary();
    while (!done() && (peek().text == "*" || peek().text == "/") && peek().kind == Token::punct) {
      const Token& op = take();
      const Value b = unary();
      if (op.text == "*") {
        a = {{a.v.x * b.v.x, a.v.y * b.v.y, a.v.z * b.v.z}, a.vector || b.vector};
      } else {
        if (b.v.x == 0.0 || b.v.y == 0.0 || b.v.z == 0.0) fail(op, "division by zero");
        a = {{a.v.x / b.v.x, a.v.y / b.v.y, a.v.z / b.v.z}, a.vector || b.vector};
      }
    }
    return a;
  }

  Value unary() {
    if (done()) fail(t_[end_ - 1], "an expression ends early");
    if (peek().kind == Token::punct && (peek().text == "-" || peek().text == "+")) {
      const bool minus = take().text == "-";
      Value v = unary();
      if (minus) v.v = -v.v;
      return v;
    }
    return primary();
  }

  Value primary() {
    const Token& t = take();
    if (t.kind == Token::number) return scalar(t.value);
    if (t.kind == Token::punct && t.text == "(") {
      const Value v = expression();
      expect(")");
      return v;
    }
    if (t.kind == Token::punct && t.text == "<") return vector_literal();
    if (t.kind == Token::word) return word(t);
    fail(t, "unexpected '" + t.text + "' in an expression");
  }

  Value vector_literal() {
    Value v{{}, true};
    v.v.x = component();
    expect(",");
    v.v.y = component();
    expect(",");
    v.v.z = component();
    expect(">");
    return v;
  }

  double component() {
    const Token& at = done() ? t_[end_ - 1] : peek();
    const Value c = expression();
    if (c.vector) fail(at, "a vector inside a vector");
    return c.v.x;
  }

  Value word(const Token& t) {
    static const std::map<std::string, Vec3> kUnit = {
        {"x", {1, 0, 0}}, {"y", {0, 1, 0}}, {"z", {0, 0, 1}}};
    if (auto u = kUnit.find(t.text); u != kUnit.end()) return {u->second, true};
    if (t.text == "pi") return scalar(std::numbers::pi);
    if (t.text == "image_width") return scalar(width_);
    if (t.text == "image_height") return scalar(height_);
    static const std::map<std::string, std::function<double(double)>> kFunctions = {
        {"sqrt", [](double a) { return std::sqrt(a); }},
        {"sin", [](double a) { return std::sin(a); }},
        {"cos", [](double a) { return std::cos(a); }},
        {"tan", [](double a) { return std::tan(a); }},
        {"atan", [](double a) { return std::atan(a); }},
        {"abs", [](double a) { return std::abs(a); }},
        {"radians", [](double a) { return a * std::numbers::pi / 180.0; }},
        {"degrees", [](double a) { return a * 180.0 / std::numbers::pi; }}};
    if (auto f = kFunctions.find(t.text); f != kFunctions.end()) {
      expect("(");
      const Value a = expression();
      expect(")");
      if (a.vector) fail(t, t.text + "() of a vector");
      const double r = f->second(a.v.x);
      if (!std::isfinite(r)) fail(t, t.text + "() is not finite here");
      return scalar(r);
    }
    fail(t, "`" + t.text +
                "` is not something landsim evaluates (declared identifiers and macros are not "
                "read: write the camera's vectors and numbers in its block)");
  }

  void expect(const std::string& what) {
    if (done()) fail(t_[end_ - 1], "expected '" + what + "' before the block ends");
    const Token& t = take();
    if (t.kind != Token::punct || t.text != what)
      fail(t, "expected '" + what + "', found '" + t.text + "'");
  }

  const std::vector<Token>& t_;
  std::size_t i_, end_;
  std::string name_;
  int width_, height_;
};

// The index of the '}' closing the '{' at `open`.
std::size_t closing_brace(const std::vector<Token>& t, std::size_t open, const std::string& name) {
  int depth = 0;
  for (std::size_t i = open; i < t.size(); ++i) {
    if (t[i].kind != Token::punct) continue;
    depth += t[i].text == "{";
    depth -= t[i].text == "}";
    if (depth == 0) return i;
  }
  throw InputError(fmt::format("{}:{}: the camera block's {{ is never closed", name, t[open].line));
}

// The camera block's items, as POV-Ray's defaults amended by the block.
struct CameraItems {
  Vec3 location{0, 0, 0}, direction{0, 0, 1}, right{1.33, 0, 0}, up{0, 1, 0}, sky{0, 1, 0};
  std::optional<Vec3> look_at;
  std::optional<double> angle;
};

const std::set<std::string> kOtherProjections = {"orthographic", "fisheye",     "ultra_wide_angle",
                                                 "omnimax",      "panoramic",   "cylinder",
                                                 "spherical",    "mesh_camera", "user_defined"};
const std::set<std::string> kTransforms = {"rotate", "translate", "scale", "matrix", "transform"};
const std::set<std::string> kFocalBlur = {"aperture",   "focal_point", "blur_samples",
                                          "confidence", "variance",    "bokeh"};

CameraItems read_items(Evaluator& e) {
  CameraItems c;
  std::map<std::string, Vec3*> vectors = {{"location", &c.location},
                                          {"direction", &c.direction},
                                          {"right", &c.right},
                                          {"up", &c.up},
                                          {"sky", &c.sky}};
  bool first = true;
  while (!e.done()) {
    const Token& item = e.take();
    if (item.kind == Token::punct && item.text == "#")
      e.fail(item, "directives (#if, #declare, ...) inside the camera block are not read");
    if (item.kind != Token::word) e.fail(item, "unexpected '" + item.text + "'");
    if (item.text == "perspective") {
    } else if (kOtherProjections.count(item.text)) {
      e.fail(item, item.text + " camera: cannot be matched, landsim's views are perspective");
    } else if (kTransforms.count(item.text)) {
      e.fail(item, item.text +
                       ": camera transforms are not read; give the camera's location and "
                       "look_at instead");
    } else if (item.text == "normal") {
      e.fail(item, "a normal-perturbed camera cannot be matched");
    } else if (auto v = vectors.find(item.text); v != vectors.end()) {
      *v->second = e.vector_of();
    } else if (item.text == "look_at") {
      c.look_at = e.vector_of();
    } else if (item.text == "angle") {
      c.angle = e.float_of(item);
    } else if (kFocalBlur.count(item.text)) {
      if (item.text == "bokeh") e.fail(item, "bokeh is not read");
      e.expression();
      spdlog::warn("camera: {} ignored: landsim renders everything in focus", item.text);
    } else if (first) {
      e.fail(item, "`" + item.text +
                       "`: a declared camera is not read; write the camera's location, look_at "
                       "and angle in the block");
    } else {
      e.fail(item, "`" + item.text + "` is not a camera item landsim reads");
    }
    first = false;
  }
  return c;
}

// POV-Ray's perspective camera from its items: the angle sets the horizontal field of view
// over |right|; look_at turns direction, right and up about the sky, keeping their lengths.
PovCamera resolve(const CameraItems& c, const std::string& where) {
  const auto fail = [&](const std::string& what) { throw InputError(where + ": camera: " + what); };
  const double right = length(c.right), up = length(c.up), direction = length(c.direction);
  if (right <= 0.0 || up <= 0.0 || direction <= 0.0)
    fail("right, up and direction must not be zero vectors");
  if (dot(c.right, cross(c.up, c.direction)) <= 0.0)
    fail("a right-handed camera (right against POV-Ray's left-handed default) mirrors the image");
  if (length(c.sky) <= 0.0 || dot(normalize(c.sky), Vec3{0, 1, 0}) < 1.0 - 1e-9)
    fail(
        "sky must point along +y: a tilted or rolled camera cannot be matched (landsim's "
        "views are upright)");
  PovCamera cam;
  cam.where = where;
  cam.location = c.location;
  if (c.look_at) {
    cam.look_at = *c.look_at;
  } else {
    // Without look_at the vectors are taken as given: they must describe an upright camera.
    const Vec3 r = normalize(c.right), d = normalize(c.direction);
    if (std::abs(r.y) > 1e-6 || std::abs(dot(r, d)) > 1e-6)
      fail(
          "without look_at, right must be level and at right angles to direction (give "
          "look_at for a camera that is turned)");
    cam.look_at = c.location + c.direction;
  }
  const Vec3 view = cam.look_at - cam.location;
  if (length(view) <= 0.0) fail("look_at is the camera's location");
  if (std::abs(normalize(view).y) > 1.0 - 1e-9) fail("a camera looking straight up or down");
  if (c.angle && (*c.angle <= 0.0 || *c.angle >= 180.0))
    fail(
        fmt::format("angle {}: expected a horizontal field of view in (0, 180) degrees", *c.angle));
  cam.horizontal_fov_deg =
      c.angle ? *c.angle : 2.0 * std::atan(0.5 * right / direction) * 180.0 / std::numbers::pi;
  cam.aspect = right / up;
  return cam;
}

}  // namespace

PovCamera parse_pov_camera(const std::string& text, const std::string& name, int image_width,
                           int image_height) {
  const std::vector<Token> t = Lexer(text, name).tokens();
  std::vector<std::size_t> blocks;  // indices of the '{' of each scene camera
  for (std::size_t i = 0; i + 1 < t.size(); ++i) {
    if (t[i].kind != Token::word || t[i].text != "camera" || t[i + 1].text != "{") continue;
    const bool declared = i > 0 && t[i - 1].kind == Token::punct && t[i - 1].text == "=";
    if (!declared) blocks.push_back(i + 1);
  }
  if (blocks.empty())
    throw InputError(name +
                     ": no camera { } block (a camera in an #include file or a #declare'd "
                     "camera without a camera block using it is not read)");
  if (blocks.size() > 1)
    throw InputError(
        fmt::format("{}: {} camera blocks (lines {} and {}): landsim cannot tell "
                    "which one POV-Ray will use; keep one",
                    name, blocks.size(), t[blocks[0]].line, t[blocks[1]].line));
  const std::size_t open = blocks[0];
  const std::size_t close = closing_brace(t, open, name);
  const std::string where = fmt::format("{}:{}", name, t[open].line);
  Evaluator e(t, open + 1, close, name, image_width, image_height);
  return resolve(read_items(e), where);
}

PovCamera read_pov_camera(const std::filesystem::path& file, int image_width, int image_height) {
  std::ifstream in(file);
  if (!in) throw InputError(file.string() + ": cannot read the POV-Ray scene");
  std::stringstream text;
  text << in.rdbuf();
  return parse_pov_camera(text.str(), file.string(), image_width, image_height);
}

renderer::View pov_camera_view(const PovCamera& camera, const renderer::View& base) {
  const double aspect = static_cast<double>(base.width) / base.height;
  if (std::abs(camera.aspect / aspect - 1.0) > 0.01)
    throw InputError(fmt::format(
        "{}: camera: right/up give an aspect of {:.4g}, the view renders {} x {} ({:.4g}): give "
        "--width/--height in the camera's ratio, or `right x*image_width/image_height`",
        camera.where, camera.aspect, base.width, base.height, aspect));
  // POV-Ray's x, y up, z -> landsim's x east, y north, z up.
  const auto scene = [](const Vec3& p) { return Vec3{p.x, p.z, p.y}; };
  renderer::View v = base;
  v.position = scene(camera.location);
  v.target = scene(camera.look_at);
  const double half = camera.horizontal_fov_deg * std::numbers::pi / 360.0;
  v.fov_y_deg = 2.0 * std::atan(std::tan(half) / aspect) * 180.0 / std::numbers::pi;
  return v;
}

}  // namespace landsim::exporters
