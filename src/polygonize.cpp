// The part as a polygon for the physics engine: curves flattened within a
// chordal tolerance, then split into convex pieces with CGAL's 2-D partition.
// Everything here is an engine input, so doubles are fine (docs/physics.md).
// GCC 12 reports a false -Wmaybe-uninitialized inside CGAL's Epic_converter
// (clang has no such warning, and would warn about the unknown group).
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Partition_traits_2.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/partition_2.h>
#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

#include <algorithm>
#include <cmath>
#include <iterator>
#include <list>

#include "fixel/curve.h"
#include "fixel/error.h"
#include "fixel/physics.h"
#include "fixel/progress.h"

namespace fixel::physics {

namespace {

using P2 = std::array<double, 2>;
using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Traits = CGAL::Partition_traits_2<K>;
constexpr std::size_t kGreeneFrom = 4096;  // outline vertices: the partition method changes here

double dist_to_segment(const P2& p, const P2& a, const P2& b) {
  const double dx = b[0] - a[0], dy = b[1] - a[1];
  const double len2 = dx * dx + dy * dy;
  double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// De Casteljau split at s in doubles.
std::pair<std::vector<P2>, std::vector<P2>> halve_at(std::vector<P2> c, double s) {
  std::vector<P2> left, right(c.size());
  const std::size_t n = c.size();
  for (std::size_t level = 0; level < n; ++level) {
    left.push_back(c[0]);
    right[n - 1 - level] = c[n - 1 - level];
    for (std::size_t i = 0; i + 1 + level < n; ++i)
      c[i] = {c[i][0] + s * (c[i + 1][0] - c[i][0]), c[i][1] + s * (c[i + 1][1] - c[i][1])};
  }
  return {left, right};
}

// Emits the start points of chords whose error is below tol. The curve lies
// in the hull of its control points, and the distance to the chord is convex,
// so the largest control-point distance bounds the chordal error.
void flatten(const std::vector<P2>& c, double tol, int depth, std::vector<P2>& out) {
  double err = 0;
  for (std::size_t k = 1; k + 1 < c.size(); ++k) err = std::max(err, dist_to_segment(c[k], c.front(), c.back()));
  if (err < tol || depth > 40) {
    out.push_back(c.front());
    return;
  }
  auto [l, r] = halve_at(c, 0.5);
  flatten(l, tol, depth + 1, out);
  flatten(r, tol, depth + 1, out);
}

P2 bezier_at(std::vector<P2> c, double s) {
  for (std::size_t level = 1; level < c.size(); ++level)
    for (std::size_t i = 0; i + level < c.size(); ++i)
      c[i] = {c[i][0] + s * (c[i + 1][0] - c[i][0]), c[i][1] + s * (c[i + 1][1] - c[i][1])};
  return c[0];
}

// Local parameters in (0, 1) of the piece's point nearest to each target
// (fixel contact points p_i, fixel points f_i) when that point is a local
// nearest point of the curve: these become outline vertices, so the engine's
// part is exact where it touches or first meets a fixel, whatever the chordal
// error elsewhere.
std::vector<double> contact_parameters(const std::vector<P2>& c, const std::vector<P2>& contacts, double size) {
  std::vector<double> out;
  for (const auto& p : contacts) {
    auto dist = [&](double s) {
      const P2 q = bezier_at(c, s);
      return std::hypot(q[0] - p[0], q[1] - p[1]);
    };
    constexpr int kSamples = 64;
    int best = 0;
    for (int k = 1; k <= kSamples; ++k)
      if (dist(double(k) / kSamples) < dist(double(best) / kSamples)) best = k;
    double lo = std::max(0.0, (best - 1.0) / kSamples), hi = std::min(1.0, (best + 1.0) / kSamples);
    for (int it = 0; it < 100; ++it) {  // golden-section search for the nearest point
      const double a = lo + 0.382 * (hi - lo), b = hi - 0.382 * (hi - lo);
      (dist(a) < dist(b) ? hi : lo) = dist(a) < dist(b) ? b : a;
    }
    const double s = (lo + hi) / 2;
    // Only near points matter (within 1/4 of the part size), and only inside.
    if (dist(s) < 0.25 * size && s > 1e-9 && s < 1 - 1e-9) out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end(), [](double a, double b) { return b - a < 1e-9; }), out.end());
  return out;
}

void outline_with(const Boundary& b, double tol, const std::vector<P2>& contacts, double size, PartPolygon& part) {
  part.outline.clear();
  part.edge_curve.clear();
  for (const auto& piece : b.pieces) {
    std::vector<P2> c;
    for (const auto& v : piece.control) c.push_back({to_double(v.x), to_double(v.y)});
    std::vector<P2> pts;
    if (piece.degree() <= 1) {
      pts.push_back(c.front());
    } else {
      double done = 0;  // split at each contact, then flatten the parts
      for (double s : contact_parameters(c, contacts, size)) {
        auto [l, r] = halve_at(c, (s - done) / (1 - done));
        flatten(l, tol, 0, pts);
        c = r;
        done = s;
      }
      flatten(c, tol, 0, pts);
    }
    for (const auto& p : pts) {
      if (!part.outline.empty() && part.outline.back() == p) continue;  // zero-length chord
      part.outline.push_back(p);
      part.edge_curve.push_back(piece.curve);
    }
  }
  while (part.outline.size() > 1 && part.outline.back() == part.outline.front()) {
    part.outline.pop_back();
    part.edge_curve.pop_back();
  }
}

double diagonal(const std::vector<P2>& pts) {
  double x0 = pts[0][0], x1 = x0, y0 = pts[0][1], y1 = y0;
  for (const auto& p : pts) {
    x0 = std::min(x0, p[0]), x1 = std::max(x1, p[0]);
    y0 = std::min(y0, p[1]), y1 = std::max(y1, p[1]);
  }
  return std::hypot(x1 - x0, y1 - y0);
}

std::string curve_name(int k) { return "body.boundary[" + std::to_string(k) + "]"; }

// Exact (filtered) self-intersection test of the closed outline: CGAL's
// sweep (O(n log n)); only when it fails, the pairwise search (O(n²),
// polled) that names two edges that meet.
void check_simple(const PartPolygon& part, RunControl* control) {
  const std::size_t n = part.outline.size();
  if (n < 3) throw SceneError("body.boundary", std::to_string(n) + " vertices", "does not enclose an area");
  std::vector<K::Point_2> v;
  for (const auto& p : part.outline) v.emplace_back(p[0], p[1]);
  if (CGAL::is_simple_2(v.begin(), v.end(), K())) return;
  auto fail = [&](std::size_t i, std::size_t j) {
    const int a = part.edge_curve[i], b = part.edge_curve[j];
    const std::string which =
        a == b ? "curve " + std::to_string(a)
               : "curves " + std::to_string(std::min(a, b)) + " and " + std::to_string(std::max(a, b));
    throw SceneError(curve_name(a), "polygonised outline",
                     "self-intersects (" + which + ", edges " + std::to_string(i) + " and " + std::to_string(j) + ")");
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (i % 256 == 0) poll(control, "push", static_cast<long>(i), static_cast<long>(n), "outline edges checked");
    const K::Segment_2 si(v[i], v[(i + 1) % n]);
    // Adjacent edges may only share their common vertex.
    const auto& c = v[(i + 2) % n];
    if (CGAL::collinear(v[i], v[(i + 1) % n], c) && (v[(i + 1) % n] - v[i]) * (c - v[(i + 1) % n]) < 0)
      fail(i, (i + 1) % n);
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;
      if (CGAL::do_intersect(si, K::Segment_2(v[j], v[(j + 1) % n]))) fail(i, j);
    }
  }
  throw SceneError("body.boundary", "polygonised outline", "is not a simple polygon");
}

}  // namespace

PartPolygon part_polygon(const Scene& scene, RunControl* control) {
  if (!scene.body.boundary)
    throw SceneError("body.boundary", "", "is missing: the physics check needs the part's outline");
  const Boundary& b = *scene.body.boundary;
  PartPolygon part;
  std::vector<P2> hull_pts;
  for (const auto& piece : b.pieces)
    for (const auto& v : piece.control) hull_pts.push_back({to_double(v.x), to_double(v.y)});
  // The control points' box bounds the part; shrink the tolerance if the
  // outline turns out smaller, so that the error stays below 1e-4 of its size.
  std::vector<P2> contacts;
  for (const auto& f : scene.fixels) {
    contacts.push_back({to_double(f.p_AoF_A.x), to_double(f.p_AoF_A.y)});
    contacts.push_back({to_double(f.p_AoF_A.x - f.gap * f.n_A.x), to_double(f.p_AoF_A.y - f.gap * f.n_A.y)});
  }
  double tol = 0.5e-4 * diagonal(hull_pts);
  outline_with(b, tol, contacts, diagonal(hull_pts), part);
  part.size = diagonal(part.outline);
  if (tol >= 0.9e-4 * part.size) {
    tol = 0.5e-4 * part.size;
    outline_with(b, tol, contacts, part.size, part);
    part.size = diagonal(part.outline);
  }
  part.chordal_tolerance = tol;
  // A large outline takes seconds to prepare: polled between the stages.
  const long n = static_cast<long>(part.outline.size());
  const bool large = part.outline.size() >= kGreeneFrom;
  if (large) poll(control, "push", 0, n, "outline vertices checked");
  check_simple(part, control);
  if (large) poll(control, "push", n, n, "outline vertices checked");

  std::list<Traits::Polygon_2> pieces;
  Traits::Polygon_2 polygon;
  for (const auto& p : part.outline) polygon.push_back(Traits::Point_2(p[0], p[1]));
  if (!polygon.is_counterclockwise_oriented())
    throw SceneError("body.boundary", "polygonised outline", "is not counter-clockwise");
  try {
    // Hertel–Mehlhorn on its triangulation; past kGreeneFrom vertices its
    // cuts cost grows about as n² (24.8 s at 40,000), so Greene's sweep
    // (O(n log n), at most four times the optimal number of pieces).
    if (polygon.size() < kGreeneFrom)
      CGAL::approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(), std::back_inserter(pieces),
                                      Traits());
    else
      CGAL::greene_approx_convex_partition_2(polygon.vertices_begin(), polygon.vertices_end(),
                                             std::back_inserter(pieces), Traits());
  } catch (const std::exception& e) {
    throw SceneError("body.boundary", "polygonised outline", std::string("cannot be partitioned: ") + e.what());
  }
  if (pieces.empty()) throw SceneError("body.boundary", "polygonised outline", "cannot be partitioned");
  for (const auto& poly : pieces) {
    std::vector<P2> piece;
    for (auto it = poly.vertices_begin(); it != poly.vertices_end(); ++it)
      piece.push_back({CGAL::to_double(it->x()), CGAL::to_double(it->y())});
    part.pieces.push_back(piece);
  }
  return part;
}

}  // namespace fixel::physics
