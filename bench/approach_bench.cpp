// Does the approach-aware set J′ predict a real engine where J does not?
// (docs/physics.md, "J′ in the engine")
//
// For seeded random convex polygons with 3 fixels (gaps up to --gap, μ up
// to --mu, in thousandths), computes J at the seat and J′, samples wrenches
// of J (random positive combinations of a piece's extreme rays, rounded to
// rationals, kept when J contains them exactly), splits them by J′, and runs
// each in Box2D as a sustained push. Then the pushing regions against J and
// J′ (resolution 1/256, frictionless pusher), with --region-pushes pushes
// at random points of every IN stretch (`region --validate`). Then, as
// `fixel push-plan` judges a point, --plan-points points of J's IN stretches
// split by J′'s exact verdict on the push in the part's frame (no partial
// band), each pushed in Box2D. Prints a Markdown table and the pooled
// seated fractions.
//
//   approach_bench [--random K] [--samples N] [--region-pushes P] [--plan-points Q] [--seed S] [--gap G]
//                  [--mu M] [--time T] [--dump DIR]   (writes each part's scene file, DIR/<name>.json)
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <random>
#include <string>

#include "fixel/approach.h"
#include "fixel/geometry.h"
#include "fixel/physics.h"
#include "fixel/region.h"
#include "fixel/region_target.h"
#include "random_parts.h"
#include "study_args.h"

namespace fp = fixel::physics;

namespace {

std::string frac(int k, int n) {
  if (n == 0) return "–";
  return std::to_string(k) + "/" + std::to_string(n) + " (" + std::to_string(std::lround(100.0 * k / n)) + "%)";
}

fixel::Rational rounded(double x) { return fixel::Rational(std::llround(x * 1e6), 1000000); }

struct Tally {
  int n = 0, seated = 0;
};

}  // namespace

int main(int argc, char** argv) {
  int random_parts = 40, samples = 20, gap = 200, mu = 500, region_pushes = 5, plan_points = 5;
  std::uint64_t seed = 7;
  std::string time = "20", dump;
  fixel::bench::check_study_args(
      argc, argv,
      "usage: approach_bench [--random N] [--samples N] [--region-pushes N] [--plan-points N] [--seed S] "
      "[--gap G] [--mu M] [--time T] [--dump DIR]" +
          std::string(fixel::bench::kEngineUsage) + "   (docs/physics.md, \"J' in the engine\")",
      fixel::bench::with_engine_args({"--random", "--samples", "--region-pushes", "--plan-points", "--seed", "--gap",
                                      "--mu", "--time", "--dump"}));
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--random") random_parts = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--samples") samples = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--region-pushes") region_pushes = fixel::bench::study_count(argv[i], argv[i + 1], 1);
    if (a == "--plan-points") plan_points = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--seed") seed = fixel::bench::study_seed(argv[i], argv[i + 1]);
    if (a == "--gap")
      gap = static_cast<int>(
          fixel::bench::study_int(argv[i], argv[i + 1], 1, 1000));  // thousandths; random_part draws % gap
    if (a == "--mu") mu = static_cast<int>(fixel::bench::study_int(argv[i], argv[i + 1], 0, 1000));
    if (a == "--time") time = argv[i + 1];
    if (a == "--dump") dump = argv[i + 1];
  }
  fp::PushOptions options;
  options.time = fixel::bench::study_positive_rational("--time", time.c_str());
  options.trajectory_samples = 1;
  fixel::bench::read_engine_args(argc, argv, options);
  std::cout << fixel::bench::engine_line(options) << "\n\n";
  std::mt19937_64 rng(seed), plan_rng(seed + 1);  // the plan points draw apart: the parts stay those of before
  std::uniform_real_distribution<double> U(0.05, 1);

  std::cout << "| part | abs(theta*) rad | J' | J' pushes seated | J \\ J' pushes seated | not seated: "
               "jammed/escaped/timeout | J region "
               "IN length, pushes seated | J' region IN length, pushes seated | J IN points: in J' seated | J IN "
               "points: not in J' seated |\n|---|---|---|---|---|---|---|---|---|---|\n";
  Tally in_all, out_all, in_large, out_large, in_small, out_small, region_j, region_a, plan_in, plan_out;
  // Points of J's IN stretches (interiors), judged by J′ in the part's frame
  // as push-plan does, and pushed at the approximate seat as `push --at` does.
  auto plan_cells = [&](const fixel::Scene& scene, const fixel::ApproachSet& A) {
    fixel::RegionOptions ro;
    ro.resolution = fixel::Rational(1, 256);
    const fixel::Region r = fixel::compute_region(scene, *fixel::sustained_target(A.J), ro);
    std::vector<const fixel::RegionInterval*> in;
    for (const auto& i : r.intervals)
      if (i.status == fixel::RegionStatus::kIn && i.u0 < i.u1) in.push_back(&i);
    Tally yes, no;
    for (int k = 0; k < plan_points && !in.empty(); ++k) {
      const fixel::RegionInterval& i = *in[plan_rng() % in.size()];
      const fixel::Rational u = i.u0 + (i.u1 - i.u0) * fixel::Rational(1 + static_cast<long>(plan_rng() % 999), 1000);
      const fixel::Curve& curve = scene.body.boundary->curves[i.curve];
      const fixel::Vec2 t = curve.derivative(u);
      const fixel::VectorQ g =
          fixel::contact_wrench(fixel::sub(curve.point(u), scene.body.p_AoCm_A), fixel::Vec2{-t.y, t.x}, 3);
      const bool in_prime = A.contains_part_frame(g);
      const auto& q = A.J.pose.approx;
      const fp::PushResult pr = fp::push(scene, fp::push_wrench_at(scene, i.curve, u, {q[0], q[1], q[2]}), options);
      Tally& tally = in_prime ? yes : no;
      ++tally.n;
      tally.seated += pr.outcome == fp::Outcome::kSeated;
    }
    plan_in.n += yes.n, plan_in.seated += yes.seated, plan_out.n += no.n, plan_out.seated += no.seated;
    return frac(yes.seated, yes.n) + " | " + frac(no.seated, no.n);
  };
  auto region_cell = [&](const fixel::Scene& scene, fixel::RegionTarget& target, Tally& pooled) {
    fixel::RegionOptions ro;
    ro.resolution = fixel::Rational(1, 256);
    const fixel::Region r = fixel::compute_region(scene, target, ro);
    fixel::Rational in = 0, all = 0;
    for (const auto& i : r.intervals) {
      all += i.u1 - i.u0;
      if (i.status == fixel::RegionStatus::kIn) in += i.u1 - i.u0;
    }
    const auto v = fp::validate_region(scene, r, fp::seated_push_model(scene), region_pushes, seed, options);
    pooled.n += v.total.pushes;
    pooled.seated += v.total.seated;
    return std::to_string(std::lround(100 * fixel::to_double(in / all))) + "%, " + frac(v.total.seated, v.total.pushes);
  };
  for (int k = 0, added = 0; added < random_parts && k < 5000; ++k) {
    std::string json;
    const auto scene = bench::random_part(rng, k, gap, mu, &json);
    if (!scene) continue;
    fixel::ApproachSet A;
    try {
      const fixel::SustainedSet J = fixel::sustained_set(*scene, false);
      if (J.empty || J.pieces.empty()) continue;
      A = fixel::approach_set(*scene, J);
    } catch (const fixel::Error&) {
      continue;
    }
    if (!A.decided) continue;
    ++added;
    if (!dump.empty()) std::ofstream(dump + "/" + scene->name + ".json") << json;
    const double theta = std::abs(A.theta_star);
    Tally in, out;
    int jammed = 0, escaped = 0, timeout = 0, in_jammed = 0, in_escaped = 0, in_timeout = 0;
    for (int s = 0, tries = 0; s < samples && tries < 50 * samples; ++tries) {
      const auto& piece = A.J.pieces[rng() % A.J.pieces.size()];
      fixel::VectorQ w(3);
      std::array<double, 3> sum{0, 0, 0};
      for (const auto& ray : piece.rays) {
        const double l = U(rng);
        for (int c = 0; c < 3; ++c) sum[c] += l * ray[c].approx();
      }
      const double norm = std::hypot(sum[0], sum[1]) + 1e-300;
      for (int c = 0; c < 3; ++c) w[c] = rounded(sum[c] / norm);
      if (!A.J.contains(w)) continue;
      ++s;
      const bool in_prime = A.contains(w);
      const fp::PushResult r = fp::push(*scene, w, options);
      const bool seated = r.outcome == fp::Outcome::kSeated;
      Tally& t = in_prime ? in : out;
      ++t.n;
      t.seated += seated;
      if (!seated) {
        (in_prime ? in_jammed : jammed) += r.outcome == fp::Outcome::kJammed;
        (in_prime ? in_escaped : escaped) += r.outcome == fp::Outcome::kEscaped;
        (in_prime ? in_timeout : timeout) += r.outcome == fp::Outcome::kTimeout;
      }
    }
    for (Tally* t : {&in_all, theta >= 0.2 ? &in_large : &in_small}) t->n += in.n, t->seated += in.seated;
    for (Tally* t : {&out_all, theta >= 0.2 ? &out_large : &out_small}) t->n += out.n, t->seated += out.seated;
    std::cout << "| " << scene->name << " | " << theta << " | " << (A.on_edges ? "on edges" : "leaves an edge") << " | "
              << frac(in.seated, in.n) << " | " << frac(out.seated, out.n) << " | J': " << in_jammed << "/"
              << in_escaped << "/" << in_timeout << "; J \\ J': " << jammed << "/" << escaped << "/" << timeout << " | "
              << region_cell(*scene, *fixel::sustained_target(A.J), region_j) << " | "
              << region_cell(*scene, *fixel::approach_target(A), region_a) << " | " << plan_cells(*scene, A) << " |\n";
  }
  std::cout << "\npooled: J' pushes seated " << frac(in_all.seated, in_all.n) << ", J \\ J' pushes seated "
            << frac(out_all.seated, out_all.n) << "\n  abs(theta*) >= 0.2 rad: J' " << frac(in_large.seated, in_large.n)
            << ", J \\ J' " << frac(out_large.seated, out_large.n) << "\n  abs(theta*) < 0.2 rad: J' "
            << frac(in_small.seated, in_small.n) << ", J \\ J' " << frac(out_small.seated, out_small.n)
            << "\nregions: J IN pushes seated " << frac(region_j.seated, region_j.n) << ", J' IN pushes seated "
            << frac(region_a.seated, region_a.n) << "\npush-plan points of J's IN stretches: in J' seated "
            << frac(plan_in.seated, plan_in.n) << ", not in J' seated " << frac(plan_out.seated, plan_out.n) << "\n";
}
