// Does a design layout's conditioning predict the engine? (docs/design.md,
// "Reading a design")
//
// For the bundled parts with an outline (with --bundled 1) and seeded
// random convex polygon parts (bench/random_parts.h), their own fixels
// dropped, runs the sustained design on N evenly spread boundary candidates
// with the friction `fixel design PART` takes. For each of the best K
// layouts it computes the sustained region of the saved layout scene (what
// `fixel design --scene-out` writes) and runs P Box2D pushes at random
// points of each IN interval (`fixel region LAYOUT --push sustained
// --validate P`). Prints one row per layout, with how many of its contacts
// lie on curved pieces, and the seated share pooled by conditioning band
// (fixel::kNearlySingular, the warning level, is a band edge).
//
//   conditioning_bench [--parts K] [--bundled 0|1] [--candidates N] [--top T]
//                      [--pushes P] [--seed S] [--time T]
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
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
  int parts = 8, bundled = 0, ncand = 12, top = 6, pushes = 5;
  std::uint64_t seed = 1;
  std::string time = "20";
  fixel::bench::check_study_args(
      argc, argv,
      "usage: conditioning_bench [--parts K] [--bundled 0|1] [--candidates N] [--top T] [--pushes P] "
      "[--seed S] [--time T]   (docs/design.md, \"Reading a design\")",
      {"--parts", "--bundled", "--candidates", "--top", "--pushes", "--seed", "--time"});
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string a = argv[i];
    if (a == "--parts") parts = std::atoi(argv[i + 1]);
    if (a == "--bundled") bundled = std::atoi(argv[i + 1]);
    if (a == "--candidates") ncand = std::atoi(argv[i + 1]);
    if (a == "--top") top = std::atoi(argv[i + 1]);
    if (a == "--pushes") pushes = std::atoi(argv[i + 1]);
    if (a == "--seed") seed = std::strtoull(argv[i + 1], nullptr, 10);
    if (a == "--time") time = argv[i + 1];
  }
  fp::PushOptions options;
  options.time = fixel::parse_rational(time);
  options.trajectory_samples = 1;
  fixel::DesignOptions o;
  o.top = top;
  o.jobs = 1;
  o.resolution = fixel::Rational(1, 256);

  // Bands of conditioning: below the warning level, up to four times it,
  // above.
  const double edges[] = {fixel::kNearlySingular, 4 * fixel::kNearlySingular};
  // [contacts: 0 straight, 1 some on curved pieces][band]
  fp::Validation band[2][3];
  int layouts_in[2][3] = {}, none_seated[2][3] = {};
  std::cout << "| part | rank | score | conditioning | contacts on curved pieces | IN pushes seated "
               "|\n|---|---|---|---|---|---|\n";
  std::vector<fixel::Scene> all;
  if (bundled) all = bench::bundled_parts(std::string(FIXEL_SOURCE_DIR) + "/data/scenes");
  std::mt19937_64 rng(seed);
  for (int k = 0, added = 0; added < parts && k < 1000; ++k)
    if (auto s = bench::random_part(rng, k)) all.push_back(*s), ++added;
  for (fixel::Scene part : all) {
    // The friction `fixel design PART` takes: the largest fixel μ (else
    // 1/10) and the scene's pusher μ.
    o.mu = part.fixels.empty() ? fixel::Rational(1, 10) : fixel::Rational(0);
    for (const auto& f : part.fixels) o.mu = std::max(o.mu, f.mu_upper());
    o.pusher_mu = part.pusher_mu_upper();
    o.pusher_mu_lo.reset();
    if (part.pusher_mu_hi) o.pusher_mu_lo = part.pusher_mu;
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
          const fixel::SustainedSet J = fixel::sustained_set(s);
          fixel::RegionOptions ro;
          ro.resolution = o.resolution;
          ro.pusher_mu = s.pusher_mu;
          const fixel::Region region = fixel::compute_region(s, *fixel::sustained_target(J), ro);
          const auto v = fp::validate_region(s, region, fp::seated_push_model(s), pushes, seed, options).total;
          const int b = l.conditioning < edges[0] ? 0 : l.conditioning < edges[1] ? 1 : 2;
          const int c = l.curved_contacts > 0;
          add(band[c][b], v);
          layouts_in[c][b] += v.pushes > 0;  // a layout without an IN interval is not pushed
          if (v.pushes > 0 && v.seated == 0) ++none_seated[c][b];
          std::cout << frac(v.seated, v.pushes) << (v.warned ? ", " + std::to_string(v.warned) + " warned" : "")
                    << " |\n";
        } catch (const fixel::Error& e) {
          std::cout << std::string(e.what()).substr(0, 60) << " |\n";
        }
      }
    } catch (const fixel::Error& e) {
      std::cout << "| " << part.name << " | – | – | – | – | " << std::string(e.what()).substr(0, 60) << " |\n";
    }
  }
  const char* names[] = {"below the warning level", "from it up to 4 times it", "above 4 times it"};
  const char* kinds[] = {"every contact on a straight edge", "a contact on a curved piece"};
  std::cout << "\npooled by conditioning (warning level " << fixel::kNearlySingular << "):\n";
  for (int c = 0; c < 2; ++c) {
    std::cout << kinds[c] << ":\n";
    for (int b = 0; b < 3; ++b) {
      const fp::Validation& v = band[c][b];
      std::cout << "  " << names[b] << ": " << layouts_in[c][b] << " layouts pushed (" << none_seated[c][b]
                << " seated no push), IN pushes seated " << frac(v.seated, v.pushes) << ", " << v.warned
                << " warned; of the others seated " << frac(v.seated - v.seated_warned, v.pushes - v.warned) << "\n";
    }
  }
}
