#pragma once
// The structure-aware fuzz pipeline, shared with the regression replay test:
// the fuzz bytes choose the numbers of a scene that always parses (exact unit
// normals, three fixels, a star-shaped boundary of polylines and clamped
// B-splines), so the work goes into seating, outcomes, simulation, the
// guaranteed set and the region rather than into the JSON parser.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "fixel/error.h"
#include "fixel/guaranteed.h"
#include "fixel/outcomes.h"
#include "fixel/progress.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "fixel/stepper.h"

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

// The exact unit vector ((1−t²)/(1+t²), 2t/(1+t²)) for t = a/b, as JSON.
inline std::string unit_from(long a, long b) {
  const long den = a * a + b * b;
  return pair("\"" + std::to_string(b * b - a * a) + "/" + std::to_string(den) + "\"",
              "\"" + std::to_string(2 * a * b) + "/" + std::to_string(den) + "\"");
}

// A scene as JSON text from the bytes. Vertices are radially ordered around
// the origin (t = tan(θ/2) increasing), so the loop is usually simple and
// counter-clockwise; the rest of the validity is up to the bytes.
inline std::string scene_from_bytes(ByteReader& in) {
  const int n = in.in(3, 10);
  std::vector<std::string> vertices;
  for (int i = 0; i < n; ++i) {
    const long t = -40 + i * (80 / n) + in.in(0, 80 / n - 1);  // spread over (−2.7, 2.7) rad
    const long den = t * t + 64;                               // t/8 = tan(θ/2)
    const int r = in.in(1, 24);                                // radius r/8
    vertices.push_back(pair("\"" + std::to_string(r * (64 - t * t)) + "/" + std::to_string(8 * den) + "\"",
                            "\"" + std::to_string(r * 16 * t) + "/" + std::to_string(8 * den) + "\""));
  }
  vertices.push_back(vertices.front());
  // Split the loop into curves: a polyline or a clamped B-spline over each run.
  std::string curves;
  for (int start = 0; start < n;) {
    const int end = std::min(n, start + in.in(1, 4));
    const bool spline = in.byte() % 2 == 1 && end - start >= 1;
    std::vector<std::string> pts(vertices.begin() + start, vertices.begin() + end + 1);
    if (!curves.empty()) curves += ", ";
    if (spline) {
      if (in.byte() % 3 == 0) {  // a control point near the origin bends the curve inwards
        const int at = 1 + in.in(0, static_cast<int>(pts.size()) - 2);
        pts.insert(pts.begin() + at, pair(in.number(2, 8), in.number(2, 8)));
      }
      const int p = std::min(static_cast<int>(pts.size()) - 1, in.in(1, 3));
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
  // Random fixel points are off the outline: marked so (docs/formats.md), so
  // that the work still goes past the scene reader.
  std::string fixels;
  for (int i = 0; i < 3; ++i) {
    fixels += std::string(i ? ", " : "") + "{\"point\": " + pair(in.number(16, 8), in.number(16, 8)) +
              ", \"normal\": " + unit_from(in.in(0, 24) - 12, in.in(1, 12)) + ", \"mu\": " + in.nonneg(10, 5) +
              ", \"gap\": " + in.nonneg(4, 16) + ", \"off_boundary\": true}";
  }
  return "{\"name\": \"structured\", \"time_step\": " + in.nonneg(4, 4, 1) +
         ", \"body\": {\"dof\": 3, \"mass\": " + in.nonneg(4, 2, 1) + ", \"velocity\": [" + in.number(2, 4) + ", " +
         in.number(2, 4) + ", " + in.number(2, 4) + "], \"boundary\": [" + curves + "]}, \"fixels\": [" + fixels +
         "], \"pusher\": {\"mu\": " + in.nonneg(2, 4) + "}}";
}

// Runs the whole library on the scene built from the bytes. Returns
// normally, or throws fixel::Error for input fixel rejects (including
// StoppedError from the region's time budget); InternalError or any other
// exception is a defect.
inline void run_structured(const std::uint8_t* data, std::size_t size) {
  ByteReader in(data, size);
  // The first byte picks the expensive steps (never for an empty input).
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
