#pragma once
// The structure-aware fuzz pipelines, shared with the regression replay test.
// The fuzz bytes choose the numbers of a scene that always parses, so the
// work goes into seating, outcomes, simulation, the guaranteed and sustained
// sets, the region and the physics rather than into the JSON parser:
//
// - run_operation (the structured_fuzz target): the first byte picks ONE
//   operation, the second the kind of scene (a star-shaped outline of
//   polylines and B-splines with off-outline fixels, a convex polygon with
//   exact unit edge normals and its fixels on the outline, or a point mass);
//   sizes are small (3–6 corners, shallow region resolution, one or two
//   samples, short pushes, 50 ms budgets) so that a typical input takes a
//   few milliseconds under the sanitizers. With `slow` (the
//   structured_slow_fuzz target) the three costly operations instead: every
//   contact mode of a three-fixel step, the guaranteed set, and fixture
//   design on a few candidates (filtered against forced exact).
// - run_structured (the regression replay only): the whole library on one
//   star-shaped scene, as the first structured target did (80–200 ms under
//   the sanitizers); kept so that its saved inputs mean what they meant.

#include <algorithm>
#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "fixel/design.h"
#include "fixel/error.h"
#include "fixel/filter.h"
#include "fixel/guaranteed.h"
#include "fixel/io.h"
#include "fixel/outcomes.h"
#include "fixel/physics.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seated_pose.h"
#include "fixel/seating.h"
#include "fixel/stepper.h"
#include "fixel/sustained.h"

namespace fixel::fuzz {

// Reads the fuzz bytes; once they run out, a fixed pseudo-random sequence
// (so that short inputs still make varied, mostly valid scenes).
class ByteReader {
 public:
  ByteReader(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}
  int byte() {
    if (pos_ < size_) return data_[pos_++];
    state_ = state_ * 1103515245u + 12345u;
    return static_cast<int>((state_ >> 16) & 0xff);
  }
  bool exhausted() const { return pos_ >= size_; }
  int in(int lo, int hi) { return lo + byte() % (hi - lo + 1); }
  // A small signed rational "n/d" as JSON text.
  std::string number(int max_num, int max_den) {
    const int num = in(0, 2 * max_num) - max_num, den = in(1, max_den);
    return "\"" + std::to_string(num) + "/" + std::to_string(den) + "\"";
  }
  std::string nonneg(int max_num, int max_den, int min_num = 0) {
    return "\"" + std::to_string(in(min_num, max_num)) + "/" + std::to_string(in(1, max_den)) + "\"";
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_, pos_ = 0;
  std::uint32_t state_ = 12345u;
};

inline std::string pair(const std::string& x, const std::string& y) { return "[" + x + ", " + y + "]"; }
inline std::string quoted(const Rational& x) { return "\"" + to_string(x) + "\""; }

// The exact unit vector ((1−t²)/(1+t²), 2t/(1+t²)) for t = a/b, as JSON.
inline std::string unit_from(long a, long b) {
  const long den = a * a + b * b;
  return pair("\"" + std::to_string(b * b - a * a) + "/" + std::to_string(den) + "\"",
              "\"" + std::to_string(2 * a * b) + "/" + std::to_string(den) + "\"");
}

// Splits a closed run of vertex texts (front repeated at the back) into
// curves: a polyline or a clamped B-spline over each run of 1–4 edges; with
// `bend`, a spline may get an extra control point near the origin.
inline std::string curves_over(ByteReader& in, const std::vector<std::string>& vertices, bool bend) {
  const int n = static_cast<int>(vertices.size()) - 1;
  std::string curves;
  for (int start = 0; start < n;) {
    const int end = std::min(n, start + in.in(1, 4));
    const bool spline = in.byte() % 2 == 1;
    std::vector<std::string> pts(vertices.begin() + start, vertices.begin() + end + 1);
    if (!curves.empty()) curves += ", ";
    if (spline) {
      if (bend && in.byte() % 3 == 0) {  // a control point near the origin bends the curve inwards
        const int at = 1 + in.in(0, static_cast<int>(pts.size()) - 2);
        pts.insert(pts.begin() + at, pair(in.number(2, 8), in.number(2, 8)));
      }
      // Without a bend, degree 1 keeps the outline a polygon (fixels stay on it).
      const int p = bend ? std::min(static_cast<int>(pts.size()) - 1, in.in(1, 3)) : 1;
      std::string knots;
      const int m = static_cast<int>(pts.size());
      for (int k = 0; k < m + p + 1; ++k) {
        const int v = k <= p ? 0 : (k >= m ? m - p : k - p);
        knots += (k ? ", \"" : "\"") + std::to_string(v) + "\"";
      }
      curves += "{\"type\": \"bspline\", \"degree\": " + std::to_string(p) + ", \"knots\": [" + knots +
                "], \"control_points\": [";
    } else {
      curves += "{\"type\": \"polyline\", \"points\": [";
    }
    for (std::size_t k = 0; k < pts.size(); ++k) curves += (k ? ", " : "") + pts[k];
    curves += "]}";
    start = end;
  }
  return curves;
}

inline std::string scene_text(ByteReader& in, const std::string& curves, const std::string& fixels) {
  return "{\"name\": \"structured\", \"time_step\": " + in.nonneg(4, 4, 1) +
         ", \"body\": {\"dof\": 3, \"mass\": " + in.nonneg(4, 2, 1) + ", \"velocity\": [" + in.number(2, 4) + ", " +
         in.number(2, 4) + ", " + in.number(2, 4) + "], \"boundary\": [" + curves + "]}, \"fixels\": [" + fixels +
         "], \"pusher\": {\"mu\": " + in.nonneg(2, 4) + "}}";
}

// A star-shaped scene as JSON text from the bytes: n corners radially
// ordered around the origin (t = tan(θ/2) increasing), so the loop is
// usually simple and counter-clockwise; polylines and B-splines of degree
// 1–3, some bent inwards; three fixels at random points, marked
// off_boundary (docs/formats.md) so that the work goes past the scene
// reader. `max_corners` bounds the size.
inline std::string scene_from_bytes(ByteReader& in, int max_corners = 10) {
  const int n = in.in(3, max_corners);
  std::vector<std::string> vertices;
  for (int i = 0; i < n; ++i) {
    const long t = -40 + i * (80 / n) + in.in(0, 80 / n - 1);  // spread over (−2.7, 2.7) rad
    const long den = t * t + 64;                               // t/8 = tan(θ/2)
    const int r = in.in(1, 24);                                // radius r/8
    vertices.push_back(pair("\"" + std::to_string(r * (64 - t * t)) + "/" + std::to_string(8 * den) + "\"",
                            "\"" + std::to_string(r * 16 * t) + "/" + std::to_string(8 * den) + "\""));
  }
  vertices.push_back(vertices.front());
  const std::string curves = curves_over(in, vertices, true);
  std::string fixels;
  for (int i = 0; i < 3; ++i) {
    fixels += std::string(i ? ", " : "") + "{\"point\": " + pair(in.number(16, 8), in.number(16, 8)) +
              ", \"normal\": " + unit_from(in.in(0, 24) - 12, in.in(1, 12)) + ", \"mu\": " + in.nonneg(10, 5) +
              ", \"gap\": " + in.nonneg(4, 16) + ", \"off_boundary\": true}";
  }
  return scene_text(in, curves, fixels);
}

// A convex polygon whose edges all have exact unit directions, with its three
// fixels exactly on the outline and along its inward normals (so seated
// pose, the sustained set and the physics run too). Edge directions are
// picked among 32 around the circle (a quarter turn times the unit vector
// of t = a/8, a = 0..7) with gaps under a half turn; the edge lengths come
// from the bytes, and two consecutive edges are lengthened exactly to close
// the loop. Corners: 3–6.
inline std::string polygon_scene_from_bytes(ByteReader& in) {
  const int k = in.in(3, 6);
  std::vector<int> slots;
  {
    std::vector<int> gaps;
    int sum = 0;
    for (int i = 0; i + 1 < k; ++i) gaps.push_back(in.in(1, 15)), sum += gaps.back();
    if (32 - sum < 1 || 32 - sum > 15) {  // no closing gap under a half turn: spread evenly
      gaps.assign(k - 1, 32 / k);
      sum = (k - 1) * (32 / k);
    }
    int s = in.in(0, 31);
    for (int i = 0; i < k; ++i) {
      slots.push_back(s % 32);
      if (i + 1 < k) s += gaps[i];
    }
  }
  std::sort(slots.begin(), slots.end());
  using V = std::array<Rational, 2>;
  std::vector<V> dir;
  for (int s : slots) {
    const long a = s % 8;
    V u{Rational(64 - a * a, 64 + a * a), Rational(16 * a, 64 + a * a)};
    for (int q = 0; q < s / 8; ++q) u = V{-u[1], u[0]};
    dir.push_back(u);
  }
  std::vector<Rational> len;
  V sum{Rational(0), Rational(0)};
  for (int i = 0; i < k; ++i) {
    len.push_back(Rational(in.in(1, 12), in.in(1, 3)));
    sum[0] += len[i] * dir[i][0];
    sum[1] += len[i] * dir[i][1];
  }
  // −sum lies in the cone of two consecutive directions (their gaps are
  // under a half turn): lengthen those two edges to close the loop.
  for (int i = 0; i < k; ++i) {
    const V& d = dir[i];
    const V& e = dir[(i + 1) % k];
    const Rational det = d[0] * e[1] - d[1] * e[0];
    if (det <= 0) continue;
    const Rational a = (-sum[0] * e[1] + sum[1] * e[0]) / det;  // a d + b e = −sum
    const Rational b = (d[0] * -sum[1] - d[1] * -sum[0]) / det;
    if (a < 0 || b < 0) continue;
    len[i] += a;
    len[(i + 1) % k] += b;
    break;
  }
  std::vector<V> corner{V{Rational(in.in(0, 8) - 8, in.in(1, 2)), Rational(in.in(0, 8) - 8, in.in(1, 2))}};
  for (int i = 0; i + 1 < k; ++i)
    corner.push_back(V{corner[i][0] + len[i] * dir[i][0], corner[i][1] + len[i] * dir[i][1]});
  std::vector<std::string> vertices;
  for (const V& c : corner) vertices.push_back(pair(quoted(c[0]), quoted(c[1])));
  vertices.push_back(vertices.front());
  const std::string curves = curves_over(in, vertices, false);
  std::string fixels;
  for (int f = 0; f < 3; ++f) {
    const int i = in.in(0, k - 1);
    const Rational t(in.in(1, 7), 8);  // inside the edge, off its corners
    const Rational x = corner[i][0] + t * len[i] * dir[i][0], y = corner[i][1] + t * len[i] * dir[i][1];
    // Inward normal of a counter-clockwise loop: the direction turned left.
    fixels += std::string(f ? ", " : "") + "{\"point\": " + pair(quoted(x), quoted(y)) +
              ", \"normal\": " + pair(quoted(-dir[i][1]), quoted(dir[i][0])) + ", \"mu\": " + in.nonneg(10, 5) +
              ", \"gap\": " + in.nonneg(4, 16) + "}";
  }
  return scene_text(in, curves, fixels);
}

// A point mass (dof 2) between two fixels.
inline std::string point_mass_scene_from_bytes(ByteReader& in) {
  std::string fixels;
  for (int i = 0; i < 2; ++i)
    fixels += std::string(i ? ", " : "") + "{\"point\": " + pair(in.number(8, 4), in.number(8, 4)) +
              ", \"normal\": " + unit_from(in.in(0, 24) - 12, in.in(1, 12)) + ", \"mu\": " + in.nonneg(10, 5) +
              ", \"gap\": " + in.nonneg(4, 16) + "}";
  return "{\"name\": \"point\", \"time_step\": " + in.nonneg(4, 4, 1) +
         ", \"body\": {\"dof\": 2, \"mass\": " + in.nonneg(4, 2, 1) + ", \"velocity\": [" + in.number(2, 4) + ", " +
         in.number(2, 4) + "]}, \"fixels\": [" + fixels + "], \"pusher\": {\"mu\": " + in.nonneg(2, 4) + "}}";
}

// A region's JSON with its one wall-clock field ("seconds") masked.
inline std::string masked_region_json(const Scene& scene, const Region& region) {
  std::string text = region_json(scene, region);
  const std::string key = "\"seconds\": ";
  for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + key.size())) {
    std::size_t end = at + key.size();
    while (end < text.size() && std::string("0123456789.e+-").find(text[end]) != std::string::npos) ++end;
    text.replace(at + key.size(), end - at - key.size(), "X");
  }
  return text;
}

// Computes a region with the filters and forced exact: the two must be the
// same JSON (the filters decide nothing the exact path would not).
template <class Compute>
void check_filtered_region(const Scene& scene, const char* what, Compute compute) {
  const std::string filtered = masked_region_json(scene, compute());
  std::string exact;
  {
    const ForceExactScope forced;
    exact = masked_region_json(scene, compute());
  }
  if (filtered != exact) throw InternalError(std::string(what) + ": the filtered and the forced-exact regions differ");
}

// Whether two design runs gave the same exact answer: the layouts, their
// exact scores and notes, and the counts (not the display doubles).
inline bool same_design(const DesignResult& a, const DesignResult& b) {
  if (a.no_layout != b.no_layout || a.layouts.size() != b.layouts.size()) return false;
  const DesignStats &s = a.stats, &t = b.stats;
  if (s.singular != t.singular || s.no_form_closure != t.no_form_closure || s.j_empty != t.j_empty ||
      s.regions != t.regions)
    return false;
  for (std::size_t k = 0; k < a.layouts.size(); ++k) {
    const DesignLayout &x = a.layouts[k], &y = b.layouts[k];
    if (x.fixels != y.fixels || x.index != y.index || x.score != y.score || x.sustained_score != y.sustained_score ||
        x.sustained_empty != y.sustained_empty || x.step_score != y.step_score || x.note != y.note)
      return false;
  }
  return true;
}

// The operations of run_operation, one per input.
enum class Operation {
  kSeat,             // seating set, its apex against every half-space
  kOutcomes,         // every contact mode of one step (dof 3: slow set only)
  kSimulate,         // 1–3 exact steps
  kSeatAndStay,      // S ∩ stability cone
  kRegion,           // subdivision at resolution 1/2–1/8, S or the paper's cone (filtered = forced exact)
  kExactRegion,      // root isolation along every Bézier piece (filtered = forced exact)
  kSample,           // 1–2 points per curve
  kPointStatus,      // one exact point test
  kGuaranteed,       // the guaranteed set G, its region (filtered = forced exact; slow set only)
  kSeatedPose,       // q* (exact or enclosed)
  kSustained,        // the sustained set J (with or without the stability check)
  kSustainedRegion,  // J's membership at one wrench, the region against J (filtered = forced exact)
  kPush,             // a short constant push in Box2D
  kCount,            // how many operations precede it: the fast set picks among them
  // Slow set only, after kCount so that the fast set's saved inputs keep
  // their meaning: fixture design on 3 boundary candidates (one layout),
  // whose ranking scores must be the same filtered and forced exact.
  kDesign
};

inline const char* operation_name(Operation op) {
  if (op == Operation::kDesign) return "design";
  static const char* const names[] = {
      "seat",         "outcomes",   "simulate",    "seat_and_stay", "region",           "exact_region", "sample",
      "point_status", "guaranteed", "seated_pose", "sustained",     "sustained_region", "push"};
  return names[static_cast<int>(op)];
}

// Runs one operation on a small scene built from the bytes. Returns
// normally, or throws fixel::Error for input fixel rejects (including
// StoppedError from the 50 ms budget of the loops that poll); InternalError
// or any other exception is a defect. The fast set (`slow` false, the
// structured_fuzz target) takes 4–40 ms per input under ASan + UBSan; the
// slow set (structured_slow_fuzz) is every contact mode of a three-fixel
// step, the guaranteed set and fixture design, 50 ms to seconds each.
inline void run_operation(const std::uint8_t* data, std::size_t size, bool slow = false) {
  ByteReader in(data, size);
  Operation op;
  if (slow) {
    static const Operation slow_set[] = {Operation::kOutcomes, Operation::kGuaranteed, Operation::kDesign};
    op = slow_set[in.byte() % 3];
  } else {
    op = static_cast<Operation>(in.byte() % static_cast<int>(Operation::kCount));
    if (op == Operation::kGuaranteed) op = Operation::kSeat;  // slow set only
  }
  const int kind = in.byte() % 4;  // 0, 1: star-shaped; 2: convex polygon; 3: point mass
  const bool needs_outline_fixels =
      op == Operation::kSeatedPose || op == Operation::kSustained || op == Operation::kSustainedRegion;
  const bool needs_boundary = needs_outline_fixels || op == Operation::kRegion || op == Operation::kExactRegion ||
                              op == Operation::kSample || op == Operation::kPointStatus || op == Operation::kPush ||
                              op == Operation::kDesign;
  // Every contact mode of a dof-3 step (4^3 exact systems) is slow: the fast
  // set enumerates the 4^2 of a point mass.
  const bool point_mass = (kind == 3 && !needs_boundary) || (!slow && op == Operation::kOutcomes);
  std::string text;
  if (point_mass)
    text = point_mass_scene_from_bytes(in);
  else if (needs_outline_fixels || kind == 2)
    text = polygon_scene_from_bytes(in);
  else
    text = scene_from_bytes(in, 6);
  const Scene scene = parse_scene(text, "structured");
  RunControl control;  // bounded work per input
  control.deadline =
      RunControl::Clock::now() + (slow ? std::chrono::milliseconds(2000) : std::chrono::milliseconds(50));
  const int dof = scene.body.dof;
  VectorQ p(dof);
  for (int k = 0; k < dof; ++k) p[k] = Rational(in.in(0, 16) - 8, in.in(1, 4));
  const int curves = scene.body.boundary ? static_cast<int>(scene.body.boundary->curves.size()) : 0;
  switch (op) {
    case Operation::kSeat: {
      const SeatingSet S = seating_set(scene);
      for (const auto& h : S.halfspaces) (void)h.contains(S.apex);
      (void)ray_magnitudes(S, p, p);
      break;
    }
    case Operation::kOutcomes:
      (void)count_outcomes(enumerate_outcomes(scene, p, &control));
      break;
    case Operation::kSimulate:
      (void)simulate(scene, {p}, in.in(1, 3), &control);
      break;
    case Operation::kSeatAndStay:
      (void)seat_and_stay(scene, seating_set(scene));
      break;
    case Operation::kRegion:
    case Operation::kExactRegion: {
      const SeatingSet S = seating_set(scene);
      RegionOptions options;
      options.resolution = Rational(1, 1 << in.in(1, 3));
      options.control = &control;
      options.cone = in.byte() % 2 ? ConeMethod::kPaper : ConeMethod::kTight;
      options.merge = in.byte() % 4 != 0;
      options.exact = op == Operation::kExactRegion;
      if (options.exact) options.digits = in.in(0, 3);
      check_filtered_region(scene, "region", [&] { return compute_region(scene, S, options); });
      break;
    }
    case Operation::kSample:
      (void)sample_region(scene, seating_set(scene), in.in(1, 2), std::nullopt, nullptr, &control);
      break;
    case Operation::kPointStatus: {
      const SeatingSet S = seating_set(scene);
      const int curve = in.in(0, std::max(0, curves - 1));
      const Curve& c = scene.body.boundary->curves[curve];
      const Rational u = c.u_begin() + (c.u_end() - c.u_begin()) * Rational(in.in(0, 16), 16);
      (void)point_status(scene, S, curve, u, Rational(in.in(0, 4), 4));
      break;
    }
    case Operation::kGuaranteed: {  // and the region against G with a frictionless pusher
      const SeatingSet S = seating_set(scene);
      const GuaranteedSet G = guaranteed_set(scene, S, &control);
      (void)lost_fraction(S, G, 2);
      if (scene.body.boundary && scene.pusher_mu == 0) {
        RegionOptions options;
        options.resolution = Rational(1, 2);
        options.control = &control;
        options.guaranteed = &G;
        check_filtered_region(scene, "region against G", [&] { return compute_region(scene, S, options); });
      }
      break;
    }
    case Operation::kSeatedPose:
      (void)seated_pose(scene);
      break;
    case Operation::kSustained:
      (void)sustained_set(scene, in.byte() % 4 == 0);
      break;
    case Operation::kSustainedRegion: {
      const SustainedSet J = sustained_set(scene, false);
      VectorQ w(3);
      for (int j = 0; j < 3; ++j) w[j] = Rational(in.in(0, 16) - 8, in.in(1, 4));
      if (!J.contains(w)) (void)J.why_not(w);
      const auto target = sustained_target(J);
      RegionOptions options;
      options.resolution = Rational(1, 1 << in.in(1, 2));
      options.control = &control;
      check_filtered_region(scene, "region against J", [&] { return compute_region(scene, *target, options); });
      break;
    }
    case Operation::kPush: {
      physics::PushOptions options;
      options.time = Rational(in.in(1, 4), 8);
      options.trajectory_samples = 10;
      (void)physics::push(scene, p, options);
      break;
    }
    case Operation::kDesign: {
      std::vector<DesignCandidate> all = boundary_candidates(scene, std::nullopt), picked;
      // Three: one layout, whose forced-exact run takes up to seconds under ASan.
      for (int k = 3; k > 0 && !all.empty(); --k) {
        const auto at = all.begin() + in.in(0, static_cast<int>(all.size()) - 1);
        picked.push_back(*at);
        all.erase(at);
      }
      DesignOptions options;
      options.push = in.byte() % 2 ? DesignPush::kStep : DesignPush::kSustained;
      options.resolution = Rational(1, 1 << in.in(1, 2));
      options.mu = Rational(in.in(0, 5), 10);
      options.pusher_mu = Rational(in.in(0, 2), 10);
      options.top = 3;
      options.jobs = 1;
      options.control = &control;
      (void)design(scene, picked, options);  // the whole run: ranking, the other model's score, J's width
      // The ranking model's batch, filtered and forced exact (the other
      // model's exact score would double the seconds this takes under ASan).
      const long triples = triple_count(static_cast<long>(picked.size()));
      DesignResult filtered, exact;
      filtered.layouts = design_batch(scene, picked, options, 0, triples, filtered.stats);
      {
        const ForceExactScope forced;
        exact.layouts = design_batch(scene, picked, options, 0, triples, exact.stats);
      }
      if (!same_design(filtered, exact))
        throw InternalError("design: the filtered and the forced-exact answers differ");
      break;
    }
    case Operation::kCount:
      break;
  }
}

// The whole library on one star-shaped scene (the first structured target;
// replayed by fuzz_regressions_test only). The first byte picks the
// expensive steps (never for an empty input): 63 mod 64 all contact modes,
// 17 mod 32 the guaranteed set.
inline void run_structured(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  const int expensive = size > 0 ? in.byte() : 0;
  const Scene scene = parse_scene(scene_from_bytes(in), "structured");
  const SeatingSet S = seating_set(scene);
  VectorQ p(3);
  for (int k = 0; k < 3; ++k) p[k] = Rational(in.in(0, 16) - 8, in.in(1, 4));
  if (expensive % 64 == 63) (void)enumerate_outcomes(scene, p);  // 4^3 exact mode systems: up to seconds
  (void)simulate(scene, {p}, in.in(1, 3));
  (void)seat_and_stay(scene, S);
  RunControl control;  // bounded work per input
  control.deadline = RunControl::Clock::now() + std::chrono::seconds(2);
  RegionOptions options;
  options.resolution = Rational(1, 4);
  options.control = &control;
  options.cone = in.byte() % 2 ? ConeMethod::kPaper : ConeMethod::kTight;
  (void)compute_region(scene, S, options);
  (void)sample_region(scene, S, 3, std::nullopt, nullptr, &control);
  if (expensive % 32 == 17) {  // the guaranteed set is the most expensive step: ~0.5 s
    const GuaranteedSet G = guaranteed_set(scene, S);
    RegionOptions g_options = options;
    g_options.guaranteed = &G;
    if (scene.pusher_mu == 0) (void)compute_region(scene, S, g_options);
  }
}

}  // namespace fixel::fuzz
