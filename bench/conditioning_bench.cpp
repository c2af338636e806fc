// Does a design layout's conditioning predict the engine? (docs/design.md,
// "Reading a design")
//
// For the bundled parts with an outline (with --bundled 1) and seeded
// random convex polygon parts (bench/random_parts.h), with --rounded R
// also R of those polygons with their corners rounded by cubic Béziers
// (their own seed stream, seed + 1), their own fixels
// dropped, runs the sustained design on N evenly spread boundary candidates
// with the friction `fixel design PART` takes. For each of the best K
// layouts it computes the sustained region of the saved layout scene (what
// `fixel design --scene-out` writes) and runs P Box2D pushes at random
// points of each IN interval (`fixel region LAYOUT --push sustained
// --validate P`). Prints one row per layout, with how many of its contacts
// lie on curved pieces, and per conditioning band (fixel::kNearlySingular,
// the warning level, is a band edge) the layouts with a push that did not
// seat and the seated share of the pushes.
//
//   conditioning_bench [--parts K] [--rounded R] [--bundled 0|1] [--candidates N]
//                      [--top T] [--pushes P] [--seed S] [--time T] [--dump DIR]
//                      [--recheck 0|1]
//
// --recheck 1 validates every layout with a push that did not seat once
// more on a finer engine (dt = h/16000, 100 velocity and 50 position
// iterations; the default is h/1000, 20 and 10): a failure that goes away
// there was the solver's, not the fixture's (docs/physics.md).
// --dump DIR writes each layout's scene as DIR/<part>_<rank>.json, to rerun
// one with `fixel region FILE --push sustained --validate P` or `fixel push`.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "fixel/design.h"
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

void add(fp::Validation& to, const fp::Validation& v) {
  to.pushes += v.pushes, to.seated += v.seated, to.warned += v.warned, to.seated_warned += v.seated_warned;
}

std::vector<fixel::DesignCandidate> spread(const std::vector<fixel::DesignCandidate>& all, int n) {
  if (n >= static_cast<int>(all.size())) return all;
  std::vector<fixel::DesignCandidate> out;
  for (int k = 0; k < n; ++k) out.push_back(all[k * all.size() / n]);
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  int parts = 8, rounded = 0, bundled = 0, ncand = 12, top = 6, pushes = 5;
  std::uint64_t seed = 1;
  std::string time = "20", dump;
  int recheck = 0;
  fixel::bench::check_study_args(
      argc, argv,
      "usage: conditioning_bench [--parts K] [--rounded R] [--bundled 0|1] [--candidates N] [--top T] [--pushes P] "
      "[--seed S] [--time T] [--dump DIR] [--recheck 0|1]   (docs/design.md, \"Reading a design\")",
      {"--parts", "--rounded", "--bundled", "--candidates", "--top", "--pushes", "--seed", "--time", "--dump",
       "--recheck"});
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--parts") parts = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--rounded") rounded = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--bundled") bundled = static_cast<int>(fixel::bench::study_int(argv[i], argv[i + 1], 0, 1));
    if (a == "--candidates") ncand = fixel::bench::study_count(argv[i], argv[i + 1], 3);  // a layout is a triple
    if (a == "--top") top = fixel::bench::study_count(argv[i], argv[i + 1]);
    if (a == "--pushes") pushes = fixel::bench::study_count(argv[i], argv[i + 1], 1);
    if (a == "--seed") seed = fixel::bench::study_seed(argv[i], argv[i + 1]);
    if (a == "--time") time = argv[i + 1];
    if (a == "--dump") dump = argv[i + 1];
    if (a == "--recheck") recheck = static_cast<int>(fixel::bench::study_int(argv[i], argv[i + 1], 0, 1));
  }
  if (!dump.empty() && !std::filesystem::is_directory(dump)) {
    std::cerr << "--dump: " << dump << " is not a folder\n";  // else every layout would fail to save
    return 2;
  }
  fp::PushOptions options;
  options.time = fixel::bench::study_positive_rational("--time", time.c_str());
  options.trajectory_samples = 1;
  fixel::bench::check_study_push_options(options);
  fixel::DesignOptions o;
  o.top = top;
  o.jobs = 1;
  o.resolution = fixel::Rational(1, 256);

  // Bands of conditioning: below the warning level, up to four times it,
  // above.
  std::vector<double> edges = {fixel::kVeryNearlySingular, 0.005, 0.01, 0.02, fixel::kNearlySingular, 0.1};
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  const std::size_t bands = edges.size() + 1;
  // [contacts: 0 straight, 1 some on curved pieces][band]
  std::vector<fp::Validation> band[2] = {std::vector<fp::Validation>(bands), std::vector<fp::Validation>(bands)};
  std::vector<int> layouts_in[2] = {std::vector<int>(bands), std::vector<int>(bands)};
  std::vector<int> some_failed[2] = {layouts_in[0], layouts_in[0]}, none_seated[2] = {layouts_in[0], layouts_in[0]};
  // With --recheck: the layouts whose pushes failed, validated again with a
  // finer engine (the others' pushes counted as they were).
  std::vector<fp::Validation> band_fine[2] = {band[0], band[1]};
  std::vector<int> some_failed_fine[2] = {layouts_in[0], layouts_in[0]};
  fp::PushOptions fine = options;
  fine.steps_per_h = 16000;
  fine.velocity_iterations = 100;
  fine.position_iterations = 50;
  std::cout << "| part | rank | score | conditioning | contacts on curved pieces | IN pushes seated "
               "|\n|---|---|---|---|---|---|\n";
  std::vector<fixel::Scene> all;
  if (bundled) all = bench::bundled_parts(std::string(FIXEL_SOURCE_DIR) + "/data/scenes");
  std::mt19937_64 rng(seed);
  for (int k = 0, added = 0; added < parts && k < 1000; ++k)
    if (auto s = bench::random_part(rng, k)) all.push_back(*s), ++added;
  std::mt19937_64 rng_rounded(seed + 1);
  for (int k = 0, added = 0; added < rounded && k < 1000; ++k)
    if (auto s = bench::random_part(rng_rounded, k, 100, 125, nullptr, true, true)) all.push_back(*s), ++added;
  for (fixel::Scene part : all) {
    // The friction `fixel design PART` takes: the largest fixel μ (else
    // 1/10) and the scene's pusher μ.
    o.mu = part.fixels.empty() ? fixel::Rational(1, 10) : fixel::Rational(0);
    for (const auto& f : part.fixels) o.mu = std::max(o.mu, f.mu_upper());
    o.pusher_mu = part.pusher_mu_upper();
    o.pusher_mu_lo = part.pusher_mu_hi ? std::optional<fixel::Rational>(part.pusher_mu) : std::nullopt;
    part.fixels.clear();
    try {
      const auto cands = spread(fixel::boundary_candidates(part, std::nullopt), ncand);
      const fixel::DesignResult r = fixel::design(part, cands, o);
      for (std::size_t rank = 0; rank < r.layouts.size(); ++rank) {
        const fixel::DesignLayout& l = r.layouts[rank];
        std::printf("| %s | %zu | %.3f | %.5f | %d | ", part.name.c_str(), rank + 1, fixel::to_double(l.score),
                    l.conditioning, l.curved_contacts);
        std::fflush(stdout);
        try {
          const fixel::Scene s = fixel::design_scene(part, r.candidates, l, static_cast<int>(rank) + 1, o);
          if (!dump.empty()) fixel::save_scene(s, dump + "/" + part.name + "_" + std::to_string(rank + 1) + ".json");
          const fixel::SustainedSet J = fixel::sustained_set(s);
          fixel::RegionOptions ro;
          ro.resolution = o.resolution;
          ro.pusher_mu = s.pusher_mu;
          const fixel::Region region = fixel::compute_region(s, *fixel::sustained_target(J), ro);
          const auto v = fp::validate_region(s, region, fp::seated_push_model(s), pushes, seed, options).total;
          const std::size_t b = std::upper_bound(edges.begin(), edges.end(), l.conditioning) - edges.begin();
          const int c = l.curved_contacts > 0;
          add(band[c][b], v);
          layouts_in[c][b] += v.pushes > 0;  // a layout without an IN interval is not pushed
          if (v.pushes > 0 && v.seated == 0) ++none_seated[c][b];
          if (v.seated < v.pushes) ++some_failed[c][b];
          std::cout << frac(v.seated, v.pushes) << (v.warned ? ", " + std::to_string(v.warned) + " warned" : "");
          if (recheck && v.seated < v.pushes) {
            // The same pushes again with a finer engine: does the failure
            // persist, or was it the solver's?
            const auto f = fp::validate_region(s, region, fp::seated_push_model(s), pushes, seed, fine).total;
            std::cout << "; finer engine " << frac(f.seated, f.pushes);
            add(band_fine[c][b], f);
            if (f.seated < f.pushes) ++some_failed_fine[c][b];
          } else {
            add(band_fine[c][b], v);
          }
          std::cout << " |\n";
        } catch (const fixel::Error& e) {
          std::cout << std::string(e.what()).substr(0, 60) << " |\n";
        }
      }
    } catch (const fixel::Error& e) {
      std::cout << "| " << part.name << " | – | – | – | – | " << std::string(e.what()).substr(0, 60) << " |\n";
    }
  }
  const char* kinds[] = {"every contact on a straight edge", "a contact on a curved piece"};
  std::cout << "\npooled by conditioning (warning level " << fixel::kNearlySingular << "):\n";
  for (int c = 0; c < 2; ++c) {
    std::cout << kinds[c] << ":\n";
    for (std::size_t b = 0; b < bands; ++b) {
      const fp::Validation& v = band[c][b];
      std::ostringstream name;
      if (b == 0)
        name << "below " << edges[0];
      else if (b == edges.size())
        name << "from " << edges[b - 1];
      else
        name << "from " << edges[b - 1] << " to " << edges[b];
      std::cout << "  " << name.str() << ": " << layouts_in[c][b] << " layouts pushed, " << some_failed[c][b]
                << " with a push not seated (" << none_seated[c][b] << " seated none), IN pushes seated "
                << frac(v.seated, v.pushes) << ", " << v.warned << " warned; of the others seated "
                << frac(v.seated - v.seated_warned, v.pushes - v.warned) << "\n";
      if (recheck)
        std::cout << "    with the failures rechecked on the finer engine: " << some_failed_fine[c][b]
                  << " layouts with a push not seated, IN pushes seated "
                  << frac(band_fine[c][b].seated, band_fine[c][b].pushes) << "\n";
    }
  }
}
