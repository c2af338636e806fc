// Does the sustained-push set J predict a real engine? (docs/physics.md)
//
// For each part (the bundled scenes with a boundary, then seeded random
// convex polygons with 3 fixels, gaps up to 1/10 and mu <= 1/8), computes
// the sustained-push region against J at the seated pose and the paper's
// one-step region against S, and runs N Box2D pushes at random points of
// every IN interval of each (`region --validate N` for both push models).
// Prints a Markdown table and the pooled seated fractions side by side.
//
//   sustained_bench [--pushes N] [--random K] [--seed S] [--time T]
//                   [--steps-per-h N] [--velocity-iterations N] [--position-iterations N]
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>

#include "fixel/physics.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "fixel/sustained.h"
#include "random_parts.h"
#include "study_args.h"

namespace fp = fixel::physics;

namespace {

std::string frac(int k, int n) {
  if (n == 0) return "–";
  return std::to_string(k) + "/" + std::to_string(n) + " (" + std::to_string(std::lround(100.0 * k / n)) + "%)";
}

// ", N warned" when some pushes warned (the engine may not resolve them).
std::string warned(const fixel::physics::Validation& v) {
  return v.warned == 0 ? "" : ", " + std::to_string(v.warned) + " warned";
}

std::string in_length(const fixel::Region& r) {
  fixel::Rational in = 0, all = 0;
  for (const auto& i : r.intervals) {
    all += i.u1 - i.u0;
    if (i.status == fixel::RegionStatus::kIn) in += i.u1 - i.u0;
  }
  return std::to_string(std::lround(100 * fixel::to_double(in / all))) + "%";
}

}  // namespace

int main(int argc, char** argv) {
  int pushes = 10, random_parts = 12;
  std::uint64_t seed = 1;
  std::string time = "20";
  fixel::bench::check_study_args(argc, argv,
                                 "usage: sustained_bench [--pushes N] [--random N] [--seed S] [--time T]" +
                                     std::string(fixel::bench::kEngineUsage) +
                                     "   (docs/physics.md, \"The sustained-push region\")",
                                 fixel::bench::with_engine_args({"--pushes", "--random", "--seed", "--time"}));
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--pushes") pushes = fixel::bench::study_count(argv[i], argv[i + 1], 1);
    if (a == "--random") random_parts = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--seed") seed = fixel::bench::study_seed(argv[i], argv[i + 1]);
    if (a == "--time") time = argv[i + 1];
  }
  fp::PushOptions options;
  options.time = fixel::bench::study_positive_rational("--time", time.c_str());
  options.trajectory_samples = 1;
  fixel::bench::read_engine_args(argc, argv, options);
  std::cout << fixel::bench::engine_line(options) << "\n\n";

  std::vector<fixel::Scene> parts = bench::bundled_parts(std::string(FIXEL_SOURCE_DIR) + "/data/scenes");
  std::mt19937_64 rng(seed);
  for (int k = 0, added = 0; added < random_parts && k < 1000; ++k)
    if (auto s = bench::random_part(rng, k)) parts.push_back(*s), ++added;

  std::cout << "| part | abs(theta*) rad | J | sustained IN length | sustained IN pushes seated | one-step IN length "
               "| one-step IN pushes seated |\n|---|---|---|---|---|---|---|\n";
  fp::Validation sustained_all, sustained_small, step_all;
  for (const auto& scene : parts) {
    std::cout << "| " << scene.name;
    fixel::RegionOptions ro;
    ro.resolution = fixel::Rational(1, 256);
    try {
      const fixel::SustainedSet J = fixel::sustained_set(scene);
      const double theta = std::abs(J.pose.approx[2]);
      const auto target = fixel::sustained_target(J);
      const fixel::Region r = fixel::compute_region(scene, *target, ro);
      const auto v = fp::validate_region(scene, r, fp::seated_push_model(scene), pushes, seed, options);
      sustained_all.pushes += v.total.pushes, sustained_all.seated += v.total.seated;
      sustained_all.warned += v.total.warned, sustained_all.seated_warned += v.total.seated_warned;
      if (theta < 0.2) sustained_small.pushes += v.total.pushes, sustained_small.seated += v.total.seated;
      std::cout << " | " << theta << " | " << (J.pieces_decided ? (J.empty ? "empty" : "non-empty") : "undecided")
                << " | " << in_length(r) << " | " << frac(v.total.seated, v.total.pushes) << warned(v.total);
    } catch (const fixel::Error& e) {
      std::cout << " | – | " << std::string(e.what()).substr(0, 60) << " | – | –";
    }
    try {
      const fixel::SeatingSet S = fixel::seating_set(scene);
      const fixel::Region r = fixel::compute_region(scene, S, ro);
      const auto model = fp::one_step_push_model(scene, S, scene.pusher_mu);
      const auto v = fp::validate_region(scene, r, model, pushes, seed, options);
      step_all.pushes += v.total.pushes, step_all.seated += v.total.seated;
      step_all.warned += v.total.warned, step_all.seated_warned += v.total.seated_warned;
      std::cout << " | " << in_length(r) << " | " << frac(v.total.seated, v.total.pushes) << warned(v.total) << " |\n";
    } catch (const fixel::Error& e) {
      std::cout << " | – | " << std::string(e.what()).substr(0, 60) << " |\n";
    }
  }
  std::cout << "\npooled: sustained-push IN pushes seated " << frac(sustained_all.seated, sustained_all.pushes)
            << " (parts with abs(theta*) < 0.2 rad: " << frac(sustained_small.seated, sustained_small.pushes)
            << "); one-step IN pushes seated " << frac(step_all.seated, step_all.pushes) << "\n"
            << "warned (the engine may not resolve them: under 50 engine steps or over 10 h, docs/physics.md): "
               "sustained "
            << sustained_all.warned << " of " << sustained_all.pushes << ", one-step " << step_all.warned << " of "
            << step_all.pushes << "; the pushes that did not warn seated: sustained "
            << frac(sustained_all.seated - sustained_all.seated_warned, sustained_all.pushes - sustained_all.warned)
            << ", one-step " << frac(step_all.seated - step_all.seated_warned, step_all.pushes - step_all.warned)
            << "\n";
}
