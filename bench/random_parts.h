#pragma once
// Seeded random convex polygon parts (corners rounded on request) with 3 fixels (exact unit normals,
// gaps up to 1/10 and mu <= 1/8 unless asked otherwise), shared by the physics studies and the
// filter tests (tests/filter_test.cpp).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "fixel/error.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"

namespace bench {

using fixel::Rational;

// Rational unit vector (cos φ, sin φ) rounded through t = tan(φ/2) = a/1000.
inline fixel::Vec2 unit(double phi) {
  const Rational t(std::lround(std::tan(phi / 2) * 1000), 1000);
  return {(1 - t * t) / (1 + t * t), 2 * t / (1 + t * t)};
}

inline std::string q(const Rational& x) { return "\"" + fixel::to_string(x) + "\""; }

// The outline's text: the closed polygon v, or with `rounded`, each corner
// v_k replaced by a cubic Bézier from a_k = v_k + r_k·(v_{k−1} − v_k) to
// b_k = v_k + r_k·(v_{k+1} − v_k) with inner control points two thirds of
// the way to v_k (the degree-raised parabola, convex and tangent to both
// edges), joined by the straight rest of each edge.
inline std::string outline_json(const std::vector<fixel::Vec2>& v, const std::vector<Rational>& r, bool rounded) {
  const int K = static_cast<int>(v.size());
  std::ostringstream s;
  auto point = [&](const fixel::Vec2& p) { return "[" + q(p.x) + "," + q(p.y) + "]"; };
  if (!rounded) {
    s << "{\"type\": \"polyline\", \"points\": [";
    for (int k = 0; k <= K; ++k) s << (k ? "," : "") << point(v[k % K]);
    s << "]}";
    return s.str();
  }
  const Rational two_thirds(2, 3);
  for (int k = 0; k < K; ++k) {
    const fixel::Vec2 &c = v[k], &prev = v[(k + K - 1) % K], &next = v[(k + 1) % K];
    const fixel::Vec2 a{c.x + r[k] * (prev.x - c.x), c.y + r[k] * (prev.y - c.y)};
    const fixel::Vec2 b{c.x + r[k] * (next.x - c.x), c.y + r[k] * (next.y - c.y)};
    const fixel::Vec2 a1{a.x + two_thirds * (c.x - a.x), a.y + two_thirds * (c.y - a.y)};
    const fixel::Vec2 b1{b.x + two_thirds * (c.x - b.x), b.y + two_thirds * (c.y - b.y)};
    const int n = (k + 1) % K;  // the next corner's start, on edge k + 1
    const fixel::Vec2 a_next{v[n].x + r[n] * (c.x - v[n].x), v[n].y + r[n] * (c.y - v[n].y)};
    s << (k ? "," : "")
      << "{\"type\": \"bspline\", \"degree\": 3, \"knots\": [\"0\",\"0\",\"0\",\"0\",\"1\",\"1\",\"1\",\"1\"], "
      << "\"control_points\": [" << point(a) << "," << point(a1) << "," << point(b1) << "," << point(b) << "]},"
      << "{\"type\": \"polyline\", \"points\": [" << point(b) << "," << point(a_next) << "]}";
  }
  return s.str();
}

// A random convex polygon as an intersection of half-planes u_k·x ≤ d_k with
// exact rational unit normals, and 3 fixels on 3 of its edges.
// `gap_max` and `mu_max` in thousandths (the defaults are the studies' 1/10
// and 1/8); `json`, when given, gets the scene file's text. With `build`
// false it only draws what a part would (the generator then stands where
// it would after the part) and returns nothing: for skipping to a known
// part without parsing and checking those before it. With `rounded`, the
// corners are rounded by cubic Béziers (outline_json) cutting 1/10 to 1/4
// of each edge at each end, drawn after everything else, so the polygon,
// its fixels (at 1/4 to 3/4 of an edge: on its straight rest) and the
// generator's state up to them are those of the unrounded part.
inline std::optional<fixel::Scene> random_part(std::mt19937_64& rng, int index, int gap_max = 100, int mu_max = 125,
                                               std::string* json = nullptr, bool build = true, bool rounded = false) {
  std::uniform_real_distribution<double> U(0, 1);
  const int K = 5 + static_cast<int>(rng() % 3);
  std::vector<fixel::Vec2> u;
  std::vector<Rational> d;
  for (int k = 0; k < K; ++k) {
    u.push_back(unit(2 * M_PI * (k + 0.35 * (U(rng) - 0.5)) / K - M_PI));
    d.push_back(Rational(800 + static_cast<long>(rng() % 400), 1000));
  }
  std::vector<fixel::Vec2> v;  // vertex k = line k ∩ line k+1
  for (int k = 0; k < K; ++k) {
    const auto &a = u[k], &b = u[(k + 1) % K];
    const Rational det = a.x * b.y - a.y * b.x;
    if (det <= 0) return std::nullopt;
    v.push_back({(d[k] * b.y - d[(k + 1) % K] * a.y) / det, (a.x * d[(k + 1) % K] - b.x * d[k]) / det});
  }
  for (const auto& p : v)
    for (int k = 0; k < K; ++k)
      if (u[k].x * p.x + u[k].y * p.y > d[k]) return std::nullopt;  // a line cut off an edge
  // Edge k runs from v[k-1] to v[k] on line k; inward normal −u_k.
  std::vector<int> edges;
  while (edges.size() < 3) {
    const int e = static_cast<int>(rng() % K);
    if (std::find(edges.begin(), edges.end(), e) == edges.end()) edges.push_back(e);
  }
  std::ostringstream fixels;
  for (int i = 0; i < 3; ++i) {
    const int e = edges[i];
    const auto &a = v[(e + K - 1) % K], &b = v[e];
    const Rational t(250 + static_cast<long>(rng() % 500), 1000);
    const Rational gap(static_cast<long>(rng() % gap_max) + 1, 1000);
    const Rational mu(static_cast<long>(rng() % (mu_max + 1)), 1000);
    fixels << (i ? "," : "") << "{\"point\": [" << q(a.x + t * (b.x - a.x)) << "," << q(a.y + t * (b.y - a.y))
           << "], \"normal\": [" << q(-u[e].x) << "," << q(-u[e].y) << "], \"mu\": " << q(mu) << ", \"gap\": " << q(gap)
           << "}";
  }
  std::vector<Rational> cut;
  if (rounded)
    for (int k = 0; k < K; ++k) cut.push_back(Rational(10 + static_cast<long>(rng() % 16), 100));
  std::ostringstream s;
  s << "{\"name\": \"" << (rounded ? "rounded" : "random") << index
    << "\", \"time_step\": \"1\", \"body\": {\"dof\": 3, \"mass\": \"1\", "
    << "\"velocity\": [\"0\",\"0\",\"0\"], \"boundary\": [" << outline_json(v, cut, rounded) << "]}, \"fixels\": ["
    << fixels.str() << "]}";
  if (!build) return std::nullopt;
  if (json) *json = s.str();
  try {
    fixel::Scene scene = fixel::parse_scene(s.str());
    fixel::seating_set(scene);  // W_n must be nonsingular
    return scene;
  } catch (const fixel::Error&) {
    return std::nullopt;
  }
}

// The bundled scenes with a boundary (dof 3), in file-name order.
inline std::vector<fixel::Scene> bundled_parts(const std::string& scene_dir) {
  std::vector<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(scene_dir)) files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  std::vector<fixel::Scene> parts;
  for (const auto& f : files) try {
      fixel::Scene s = fixel::load_scene(f);
      if (s.body.boundary && s.body.dof == 3) parts.push_back(s);
    } catch (const fixel::Error&) {
    }
  return parts;
}

}  // namespace bench
