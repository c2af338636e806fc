// Reading a scene from JSON text: every field checked, and named with its
// JSON path in errors.
#include "fixel/scene_json.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <vector>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/internal/json_exact.h"
#include "fixel/on_boundary.h"
#include "fixel/progress.h"

namespace fixel {

namespace {

using json = nlohmann::json;

std::string describe(const json& v) {
  std::string s = v.dump();
  if (s.size() > 80) s = s.substr(0, 77) + "...";
  return s;
}

// Checks that `obj` is an object whose keys are all in `allowed`.
std::string join(const std::string& path, const std::string& key) { return path.empty() ? key : path + "." + key; }

// `path` is empty for the document root, which `source` then names.
void expect_object(const json& obj, const std::string& path, const std::set<std::string>& allowed,
                   const std::string& source = "") {
  if (!obj.is_object()) throw SceneError(path.empty() ? source : path, describe(obj), "must be a JSON object");
  for (const auto& item : obj.items())
    if (!allowed.count(item.key()))
      throw SceneError(join(path, item.key()), describe(item.value()), "is not a known field");
}

const json& require(const json& obj, const std::string& key, const std::string& path) {
  auto it = obj.find(key);
  if (it == obj.end()) throw SceneError(join(path, key), "", "is missing");
  return *it;
}

Rational number(const json& v, const std::string& path) {
  if (!v.is_string()) throw ParseError(path, describe(v), "is not an exact number");
  return parse_rational(v.get<std::string>(), path);
}

VectorQ vector(const json& v, const std::string& path, int expected_length, const std::string& why) {
  if (!v.is_array()) throw SceneError(path, describe(v), "must be an array of numbers");
  if (static_cast<int>(v.size()) != expected_length)
    throw SceneError(
        path, describe(v),
        "has " + std::to_string(v.size()) + " entries but " + why + " needs " + std::to_string(expected_length));
  VectorQ out(expected_length);
  for (int i = 0; i < expected_length; ++i) out[i] = number(v[i], path + "[" + std::to_string(i) + "]");
  return out;
}

Vec2 vec2(const json& v, const std::string& path) {
  VectorQ q = vector(v, path, 2, "a planar point or direction");
  return {q[0], q[1]};
}

std::vector<Vec2> points(const json& v, const std::string& path, RunControl* control) {
  if (!v.is_array()) throw SceneError(path, describe(v), "must be an array of [x, y] points");
  std::vector<Vec2> out;
  const long total = static_cast<long>(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (i % 256 == 0) poll(control, "load", static_cast<long>(i), total, "points read");
    out.push_back(vec2(v[i], path + "[" + std::to_string(i) + "]"));
  }
  return out;
}

Boundary parse_boundary(const json& v, RunControl* control) {
  const std::string path = "body.boundary";
  if (!v.is_array()) throw SceneError(path, describe(v), "must be an array of curves");
  std::vector<Curve> curves;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string cpath = path + "[" + std::to_string(k) + "]";
    const json& c = v[k];
    if (!c.is_object()) throw SceneError(cpath, describe(c), "must be a JSON object");
    const json& type = require(c, "type", cpath);
    Curve curve;
    if (type == "polyline") {
      expect_object(c, cpath, {"type", "points"});
      curve.type = Curve::Type::kPolyline;
      curve.points = points(require(c, "points", cpath), cpath + ".points", control);
    } else if (type == "bspline") {
      expect_object(c, cpath, {"type", "degree", "knots", "control_points"});
      curve.type = Curve::Type::kBSpline;
      const Rational degree = number(require(c, "degree", cpath), cpath + ".degree");
      if (degree < 1 || degree > 20 || boost::multiprecision::denominator(degree) != 1)
        throw SceneError(cpath + ".degree", to_string(degree), "must be an integer from 1 to 20");
      curve.degree = static_cast<int>(boost::multiprecision::numerator(degree));
      curve.points = points(require(c, "control_points", cpath), cpath + ".control_points", control);
      const json& knots = require(c, "knots", cpath);
      if (!knots.is_array()) throw SceneError(cpath + ".knots", describe(knots), "must be an array of numbers");
      for (std::size_t i = 0; i < knots.size(); ++i)
        curve.knots.push_back(number(knots[i], cpath + ".knots[" + std::to_string(i) + "]"));
    } else {
      throw SceneError(cpath + ".type", describe(type), "must be \"polyline\" or \"bspline\"");
    }
    curves.push_back(std::move(curve));
  }
  return make_boundary(std::move(curves), path, control);
}

// A friction coefficient "mu" or an interval ["lo", "hi"] (0 <= lo <= hi).
void parse_friction(const json& v, const std::string& path, Rational& lo, std::optional<Rational>& hi) {
  if (v.is_array()) {
    const VectorQ range = vector(v, path, 2, "a friction interval [lo, hi]");
    lo = range[0];
    check_nonnegative(lo, path + "[0]");
    if (range[1] < lo) throw SceneError(path, "[" + to_string(lo) + ", " + to_string(range[1]) + "]", "has lo > hi");
    if (range[1] != lo) hi = range[1];
    return;
  }
  lo = number(v, path);
  check_nonnegative(lo, path);
}

std::string approx_text(double v) {
  if (std::abs(v) < 1e-9) v = 0;  // display: float noise
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

// A suggestion for a direction that is not an exact unit vector.
std::string suggest_unit(double radians) {
  const Vec2 u = nearby_exact_unit(radians);
  return "the nearest exact unit normal (within 1e-9 rad) is [\"" + to_string(u.x) + "\", \"" + to_string(u.y) + "\"]";
}

// A fixel's normal: ["x", "y"] of unit length, {"degrees": "D"}, or
// "boundary" (the outline's inward normal at the point, filled in later).
Vec2 parse_normal(const json& v, const std::string& path, bool& from_boundary) {
  from_boundary = false;
  if (v.is_string() && v.get<std::string>() == "boundary") {
    from_boundary = true;
    return {Rational(0), Rational(0)};
  }
  if (v.is_object()) {
    expect_object(v, path, {"degrees"});
    const Rational deg = number(require(v, "degrees", path), path + ".degrees");
    // Niven: the only rational angles in degrees with rational sine and
    // cosine are the multiples of 90°.
    const Rational quarter = deg / 90;
    if (boost::multiprecision::denominator(quarter) != 1) {
      // The hint from deg mod 360, exactly: 1e400 degrees has no double.
      const Rational turns = deg / 360;
      Rational reduced =
          deg - 360 * Rational(boost::multiprecision::numerator(turns) / boost::multiprecision::denominator(turns));
      if (reduced < 0) reduced += 360;
      throw SceneError(path + ".degrees", to_string(deg),
                       "is not an exact direction: a rational angle in degrees has rational cosine and sine only at "
                       "multiples of 90°; " +
                           suggest_unit(to_double(reduced) * M_PI / 180));
    }
    const int k = static_cast<int>(((boost::multiprecision::numerator(quarter) % 4) + 4) % 4);
    static const int cs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
    return {Rational(cs[k][0]), Rational(cs[k][1])};
  }
  if (v.is_string())
    throw SceneError(path, describe(v), "must be [\"x\", \"y\"], {\"degrees\": \"D\"} or \"boundary\"");
  const Vec2 n = vec2(v, path);
  if (n.x * n.x + n.y * n.y != 1) {
    std::string hint = "x²+y² must be exactly 1, e.g. (3/5, 4/5)";
    if (!is_zero(n)) {
      if (const auto u = exact_unit(n))
        hint += "; normalised exactly it is [\"" + to_string(u->x) + "\", \"" + to_string(u->y) + "\"]";
      else
        hint += "; " + suggest_unit(std::atan2(to_double(n.y), to_double(n.x)));
    }
    throw SceneError(path, "(" + to_string(n.x) + ", " + to_string(n.y) + ")", "is not of unit length (" + hint + ")");
  }
  return n;
}

// "normal": "boundary": the outline's inward normal at the point, which must
// be an exact unit vector there.
Vec2 boundary_normal(const Scene& scene, const Vec2& p, int i) {
  const std::string path = "fixels[" + std::to_string(i) + "]";
  if (!scene.body.boundary) throw SceneError(path + ".normal", "\"boundary\"", "needs body.boundary");
  const BoundaryFit fit = fit_to_boundary(*scene.body.boundary, p, nullptr);
  const std::string pt = "(" + to_string(p.x) + ", " + to_string(p.y) + ")";
  if (!fit.on_boundary)
    throw SceneError(path + ".point", pt,
                     "is not on the part's outline (" + approx_text(fit.distance) +
                         " m from it), so \"normal\": \"boundary\" has no normal to take");
  const std::string near =
      "≈ (" + approx_text(fit.inward_normal_approx[0]) + ", " + approx_text(fit.inward_normal_approx[1]) + ")";
  const double angle = std::atan2(fit.inward_normal_approx[1], fit.inward_normal_approx[0]);
  if (fit.corner)
    throw SceneError(path + ".normal", "\"boundary\"",
                     "is ambiguous: " + pt +
                         " is a corner of the outline; give the normal explicitly, between the "
                         "two edges' inward normals (their bisector is " +
                         near + ")");
  if (!fit.inward_normal)
    throw SceneError(path + ".normal", "\"boundary\"",
                     "cannot be taken exactly: " + pt + " is at an irrational parameter of body.boundary[" +
                         std::to_string(fit.curve) + "], where the inward normal " + near +
                         " is not rational; give it explicitly (" + suggest_unit(angle) + ")");
  const auto u = exact_unit(*fit.inward_normal);
  if (!u)
    throw SceneError(path + ".normal", "\"boundary\"",
                     "cannot be taken exactly: the inward normal at " + pt + " is " + near +
                         ", whose length is irrational (the tangent there is (" + to_string(-fit.inward_normal->y) +
                         ", " + to_string(fit.inward_normal->x) +
                         ")); move the point to where the tangent has a "
                         "rational length, or give the normal (" +
                         suggest_unit(angle) + ")");
  return *u;
}

int parse_dof(const json& v) {
  if (!v.is_string()) throw SceneError("body.dof", describe(v), "must be 2 or 3");
  const std::string s = v.get<std::string>();
  if (s != "2" && s != "3") throw SceneError("body.dof", s, "must be 2 (point mass) or 3 (planar rigid body)");
  return s == "2" ? 2 : 3;
}

}  // namespace

Scene parse_scene(const std::string& json_text, const std::string& source, RunControl* control) {
  poll(control, "load", 0, 0, "JSON documents parsed");
  const json root = internal::parse_json_exact(json_text, source, {"name", "description"});
  expect_object(root, "", {"name", "description", "time_step", "body", "fixels", "pusher", "background_impulse"},
                source);

  Scene scene;
  const auto name_it = root.find("name");
  if (name_it != root.end()) {
    if (!name_it->is_string()) throw SceneError("name", describe(*name_it), "must be a string");
    scene.name = name_it->get<std::string>();
  }
  const auto description_it = root.find("description");
  if (description_it != root.end()) {
    if (!description_it->is_string()) throw SceneError("description", describe(*description_it), "must be a string");
    scene.description = description_it->get<std::string>();
  }
  scene.time_step = number(require(root, "time_step", ""), "time_step");
  check_positive(scene.time_step, "time_step");

  const json& body = require(root, "body", "");
  expect_object(body, "body", {"dof", "mass", "inertia", "velocity", "center_of_mass", "boundary"});
  Body& b = scene.body;
  b.dof = parse_dof(require(body, "dof", "body"));
  const bool has_boundary = body.contains("boundary");
  if (has_boundary) b.boundary = std::make_shared<const Boundary>(parse_boundary(body.at("boundary"), control));
  // With a boundary, mass defaults to the area (density 1) and the centre of
  // mass to the area centroid.
  if (body.contains("mass") || !has_boundary) {
    b.mass = number(require(body, "mass", "body"), "body.mass");
    check_positive(b.mass, "body.mass");
  } else {
    b.mass = b.boundary->mass.area;
    b.mass_from_area = true;
  }
  if (body.contains("center_of_mass"))
    b.p_AoCm_A = vec2(body.at("center_of_mass"), "body.center_of_mass");
  else
    b.p_AoCm_A = has_boundary ? b.boundary->mass.centroid : Vec2{Rational(0), Rational(0)};
  b.center_of_mass_from_area = has_boundary && !body.contains("center_of_mass");
  if (b.dof == 3) {
    if (body.contains("inertia")) {
      b.inertia = number(body.at("inertia"), "body.inertia");
      check_positive(b.inertia, "body.inertia");
    } else if (has_boundary) {
      // Uniform density m / A about the centre of mass.
      b.inertia = b.mass / b.boundary->mass.area * b.boundary->mass.polar_moment_about(b.p_AoCm_A);
      b.inertia_from_area = true;
    } else {
      throw SceneError("body.inertia", "", "is missing (required for dof 3 without a boundary)");
    }
  } else if (body.contains("inertia")) {
    throw SceneError("body.inertia", describe(body.at("inertia")), "is not allowed for a point mass (dof 2)");
  }
  b.velocity = body.contains("velocity")
                   ? vector(body.at("velocity"), "body.velocity", b.dof, "dof " + std::to_string(b.dof))
                   : VectorQ::Zero(b.dof);

  const json& fixels = require(root, "fixels", "");
  if (!fixels.is_array()) throw SceneError("fixels", describe(fixels), "must be an array");
  for (std::size_t i = 0; i < fixels.size(); ++i) {
    const std::string path = "fixels[" + std::to_string(i) + "]";
    const json& f = fixels[i];
    expect_object(f, path, {"point", "normal", "mu", "gap", "off_boundary"});
    Fixel fx;
    fx.p_AoF_A = vec2(require(f, "point", path), path + ".point");
    bool from_boundary = false;
    fx.n_A = parse_normal(require(f, "normal", path), path + ".normal", from_boundary);
    if (f.contains("off_boundary")) {
      if (!f.at("off_boundary").is_boolean())
        throw SceneError(path + ".off_boundary", describe(f.at("off_boundary")), "must be true or false");
      fx.off_boundary = f.at("off_boundary").get<bool>();
    }
    if (from_boundary)  // the outline is parsed already: take its normal
      fx.n_A = boundary_normal(scene, fx.p_AoF_A, static_cast<int>(i));
    else
      check_unit_normal(fx.n_A, path + ".normal");
    parse_friction(require(f, "mu", path), path + ".mu", fx.mu, fx.mu_hi);
    fx.gap = number(require(f, "gap", path), path + ".gap");
    check_nonnegative(fx.gap, path + ".gap");
    scene.fixels.push_back(fx);
  }

  scene.pusher_mu = Rational(0);
  if (root.contains("pusher")) {
    const json& pusher = root.at("pusher");
    expect_object(pusher, "pusher", {"mu"});
    if (pusher.contains("mu")) {
      parse_friction(pusher.at("mu"), "pusher.mu", scene.pusher_mu, scene.pusher_mu_hi);
    }
  }
  scene.background_impulse =
      root.contains("background_impulse")
          ? vector(root.at("background_impulse"), "background_impulse", b.dof, "dof " + std::to_string(b.dof))
          : VectorQ::Zero(b.dof);
  check_fixels_on_boundary(scene);
  return scene;
}

Scene load_scene(const std::string& path, RunControl* control) {
  std::error_code ignored;
  if (std::filesystem::is_directory(path, ignored)) throw InputError(path, "", "is a directory, not a scene file");
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    const int reason = errno;  // the open's (ENOENT, EACCES, ...), when the library set it
    throw InputError(path, "",
                     std::string("cannot be opened") + (reason ? std::string(": ") + std::strerror(reason) : ""));
  }
  return read_scene(in, path, control);
}

Scene read_scene(std::istream& in, const std::string& source, RunControl* control) {
  std::string text;
  constexpr std::size_t kChunk = std::size_t(1) << 20;
  std::vector<char> chunk(kChunk);
  while (in) {
    in.read(chunk.data(), static_cast<std::streamsize>(kChunk));
    text.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxSceneBytes)
      throw InputError(source, "", "is larger than 256 MiB: not a scene file (is it /dev/zero or an endless stream?)");
    poll(control, "load", static_cast<long>(text.size() >> 20), 0, "MiB read");
  }
  if (in.bad()) throw InputError(source, "", "cannot be read");
  return parse_scene(text, source, control);
}

VectorQ parse_impulse(const std::string& text, int dof, const std::string& field) {
  const std::vector<Rational> values = parse_rational_list(text, field);
  if (static_cast<int>(values.size()) != dof)
    throw InputError(
        field, "\"" + text + "\"",
        "has " + std::to_string(values.size()) + " components but the scene has dof " + std::to_string(dof));
  VectorQ p(dof);
  for (int i = 0; i < dof; ++i) p[i] = values[i];
  return p;
}

}  // namespace fixel
