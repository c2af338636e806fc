// What the paper's one-step model is worth in a real engine (docs/physics.md).
//
// For each part (the bundled scenes with a boundary, then seeded random
// convex polygons with 3 fixels), samples impulses p in S, impulses outside
// S, and boundary points of the one-step pushing region (p = τ (d, r ⊗ d)),
// and runs each in Box2D three times: p delivered at once then free for h,
// and p/h held for h (both counted when every gap is below 1e-4 of the part
// size at t = h), and p/h held until an outcome or 20 h ("sustained":
// outcome seated). Prints a Markdown table.
//
//   physics_bench [--samples N] [--random K] [--seed S] [--time T]
//                 [--steps-per-h N] [--velocity-iterations N] [--position-iterations N]
// (the engine options apply to all three pushes)
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <random>
#include <sstream>
#include <string>

#include "fixel/error.h"
#include "fixel/physics.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/seating.h"
#include "random_parts.h"
#include "study_args.h"

namespace fp = fixel::physics;
using fixel::Rational;

namespace {

struct Count {
  int n = 0, at_once = 0, at_h = 0, sustained = 0;
  // Sustained pushes the engine may not resolve (their run warned), and of
  // those the seated ones.
  int warned = 0, seated_warned = 0;
  void add(const Count& o) {
    n += o.n, at_once += o.at_once, at_h += o.at_h, sustained += o.sustained;
    warned += o.warned, seated_warned += o.seated_warned;
  }
};

std::string frac(int k, int n) {
  if (n == 0) return "–";
  std::ostringstream o;
  o << k << "/" << n << " (" << std::lround(100.0 * k / n) << "%)";
  return o.str();
}

std::string row(const Count& c) {
  return " | " + frac(c.at_once, c.n) + " | " + frac(c.at_h, c.n) + " | " + frac(c.sustained, c.n);
}

// Runs p as p/h for h and as a sustained push.
void run(const fixel::Scene& scene, const fp::Wrench& w, const fp::PushOptions& sustained, Count& c) {
  fp::PushOptions one;
  one.steps_per_h = sustained.steps_per_h;  // the engine's accuracy, as asked for
  one.velocity_iterations = sustained.velocity_iterations;
  one.position_iterations = sustained.position_iterations;
  one.time = 1;
  one.stop_at_outcome = false;
  one.trajectory_samples = 1;
  auto closed = [](const fp::PushResult& r) {
    bool all = true;
    for (double g : r.final_gaps) all = all && g < r.gap_tolerance;
    return all;
  };
  ++c.n;
  c.at_h += closed(fp::push(scene, w, one));
  // The impulse p = h·w delivered at once, then no force.
  const double h = fixel::to_double(scene.time_step);
  one.impulse = std::array<double, 3>{h * w.fx, h * w.fy, h * w.m};
  c.at_once += closed(fp::push(scene, fp::Wrench{}, one));
  const fp::PushResult held = fp::push(scene, w, sustained);
  const bool seated = held.outcome == fp::Outcome::kSeated;
  c.sustained += seated;
  c.warned += !held.warnings.empty();
  c.seated_warned += seated && !held.warnings.empty();
}

// The sustained pushes that warned, and the seated share of the others.
std::string warned_text(const char* what, const Count& c) {
  return std::string(what) + ": " + std::to_string(c.warned) + " of " + std::to_string(c.n) +
         " warned; the others seated " + frac(c.sustained - c.seated_warned, c.n - c.warned);
}

fp::Wrench as_force(const fixel::Scene& scene, const std::array<double, 3>& p) {
  const double h = fixel::to_double(scene.time_step);
  return {p[0] / h, p[1] / h, p[2] / h};
}

}  // namespace

int main(int argc, char** argv) {
  int samples = 40, random_parts = 8;
  std::uint64_t seed = 1;
  std::string time = "20";
  fixel::bench::check_study_args(argc, argv,
                                 "usage: physics_bench [--samples N] [--random N] [--seed S] [--time T]" +
                                     std::string(fixel::bench::kEngineUsage) + "   (docs/physics.md, \"Measured\")",
                                 fixel::bench::with_engine_args({"--samples", "--random", "--seed", "--time"}));
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--samples") samples = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--random") random_parts = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--seed") seed = fixel::bench::study_seed(argv[i], argv[i + 1]);
    if (a == "--time") time = argv[i + 1];
  }
  fp::PushOptions sustained;
  sustained.time = fixel::bench::study_positive_rational("--time", time.c_str());
  sustained.trajectory_samples = 1;
  fixel::bench::read_engine_args(argc, argv, sustained);
  std::cout << fixel::bench::engine_line(sustained) << "\n\n";

  std::vector<fixel::Scene> parts = bench::bundled_parts(std::string(FIXEL_SOURCE_DIR) + "/data/scenes");
  std::mt19937_64 rng(seed);
  for (int k = 0, added = 0; added < random_parts && k < 1000; ++k)
    if (auto s = bench::random_part(rng, k)) parts.push_back(*s), ++added;

  std::cout << "| part | in S: p at once | in S: p/h for h | in S: sustained | outside S: p at once | "
               "outside S: p/h for h | outside S: sustained | region: p at once | region: p/h for h | "
               "region: sustained |\n|---|---|---|---|---|---|---|---|---|---|\n";
  Count all_in, all_out, all_region;
  std::uniform_real_distribution<double> U(0, 1);
  for (const auto& scene : parts) {
    const fixel::SeatingSet S = fixel::seating_set(scene);
    const double apex = std::hypot(fixel::to_double(S.apex[0]), fixel::to_double(S.apex[1]));
    Count in, out, region;
    for (int k = 0; k < samples; ++k) {
      std::array<double, 3> p{};
      for (int j = 0; j < 3; ++j) p[j] = fixel::to_double(S.apex[j]);
      for (const auto& ray : S.rays) {
        const double lambda = U(rng) * apex;
        for (int j = 0; j < 3; ++j) p[j] += lambda * fixel::to_double(ray[j]);
      }
      run(scene, as_force(scene, p), sustained, in);
    }
    for (int k = 0; k < samples;) {
      std::array<double, 3> p{};
      const double a = 2 * M_PI * U(rng), b = std::acos(2 * U(rng) - 1), r = 2 * apex * U(rng);
      for (int j = 0; j < 3; ++j) p[j] = fixel::to_double(S.apex[j]);
      p[0] += r * std::sin(b) * std::cos(a), p[1] += r * std::sin(b) * std::sin(a), p[2] += r * std::cos(b);
      fixel::VectorQ pq(3);
      for (int j = 0; j < 3; ++j) pq[j] = Rational(p[j]);  // exact value of the double
      if (S.contains(pq)) continue;
      run(scene, as_force(scene, p), sustained, out);
      ++k;
    }
    fixel::RegionOptions ro;
    ro.resolution = Rational(1, 256);
    const fixel::Region reg = fixel::compute_region(scene, S, ro);
    const auto model = fp::one_step_push_model(scene, S, scene.pusher_mu);
    std::vector<const fixel::RegionInterval*> ins;
    for (const auto& iv : reg.intervals)
      if (iv.status == fixel::RegionStatus::kIn) ins.push_back(&iv);
    for (int k = 0; k < samples && !ins.empty(); ++k) {
      const auto& iv = *ins[rng() % ins.size()];
      const Rational u = iv.u0 + (iv.u1 - iv.u0) * Rational(static_cast<long>(rng() >> 44), 1L << 20);
      run(scene, model(iv, u), sustained, region);
    }
    std::cout << "| " << scene.name << row(in) << row(out) << row(region) << " |\n" << std::flush;
    all_in.add(in), all_out.add(out), all_region.add(region);
  }
  std::cout << "| **pooled**" << row(all_in) << row(all_out) << row(all_region) << " |\n";
  std::cout << "\nsustained pushes the engine may not resolve (under 50 engine steps or over 10 h, docs/physics.md), "
               "pooled: "
            << warned_text("in S", all_in) << "; " << warned_text("outside S", all_out) << "; "
            << warned_text("region", all_region) << "\n";
  return 0;
}
