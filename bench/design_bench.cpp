// Fixture design throughput (docs/design.md): layouts scored per second on
// one thread and the speedup with 2 threads, every triple scored, on a
// bundled part; with --bound, the bounded search against scoring every
// triple, side by side in one run (seconds, counts, the same layouts);
// with --parts, per bundled part, the best layout's score against the
// layout shipped in the scene file; and, with --stages, what one layout's
// evaluation costs.
//
//   design_bench [--part NAME] [--candidates N] [--resolution R] [--jobs J]
//                [--stages] [--parts] [--bound] [--top K]
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>

#include "fixel/design.h"
#include "fixel/region_target.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "fixel/sustained.h"
#include "study_args.h"

namespace {

fixel::Scene bundled(const std::string& name) {
  return fixel::load_scene(std::string(FIXEL_SOURCE_DIR) + "/data/scenes/" + name + ".json");
}

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// Evenly spread n of the part's 24 default candidates... or more: a spacing
// of perimeter / n.
std::vector<fixel::DesignCandidate> candidates(const fixel::Scene& part, int n) {
  auto all = fixel::boundary_candidates(part, std::nullopt);
  if (n <= static_cast<int>(all.size())) {
    std::vector<fixel::DesignCandidate> out;
    for (int k = 0; k < n; ++k) out.push_back(all[k * all.size() / n]);
    return out;
  }
  double perimeter = 0;  // rough, for the spacing only
  for (const auto& p : part.body.boundary->pieces)
    for (int j = 0; j < 64; ++j) {
      const auto a = p.point(fixel::Rational(j, 64)), b = p.point(fixel::Rational(j + 1, 64));
      perimeter += std::hypot(fixel::to_double(b.x - a.x), fixel::to_double(b.y - a.y));
    }
  const long long q = 1 << 20;
  return fixel::boundary_candidates(part, fixel::Rational(static_cast<long long>(perimeter / n * q), q));
}

void stages(const fixel::Scene& part, const std::vector<fixel::DesignCandidate>& c, const fixel::DesignOptions& o) {
  double t_scene = 0, t_j = 0, t_jregion = 0, t_s = 0, t_sregion = 0;
  int n = 0, nonempty = 0;
  const long T = fixel::triple_count(static_cast<long>(c.size()));
  for (long idx = 0; idx < T && n < 60; idx += std::max(1L, T / 60)) {
    const auto f = fixel::triple_at(static_cast<long>(c.size()), idx);
    auto t0 = std::chrono::steady_clock::now();
    const fixel::Scene s = fixel::layout_scene(part, c, f, o, false);
    t_scene += seconds_since(t0);
    try {
      t0 = std::chrono::steady_clock::now();
      const auto J = fixel::sustained_set(s, false);
      t_j += seconds_since(t0);
      if (!J.empty) {
        ++nonempty;
        t0 = std::chrono::steady_clock::now();
        fixel::RegionOptions ro;
        ro.resolution = o.resolution;
        ro.pusher_mu = o.pusher_mu;
        compute_region(s, *fixel::sustained_target(J), ro);
        t_jregion += seconds_since(t0);
      }
      const fixel::Scene st = fixel::layout_scene(part, c, f, o, true);
      t0 = std::chrono::steady_clock::now();
      const auto S = fixel::seating_set(st);
      t_s += seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
      fixel::RegionOptions ro;
      ro.resolution = o.resolution;
      ro.pusher_mu = o.pusher_mu;
      compute_region(st, S, ro);
      t_sregion += seconds_since(t0);
    } catch (const fixel::Error&) {
      continue;  // singular
    }
    ++n;
  }
  std::cout << "per layout (mean of " << n << " non-singular, " << nonempty << " with J non-empty), ms: scene "
            << 1e3 * t_scene / n << ", J " << 1e3 * t_j / n << ", J region " << 1e3 * t_jregion / std::max(nonempty, 1)
            << ", S " << 1e3 * t_s / n << ", S region " << 1e3 * t_sregion / n << "\n";
}

bool same_layouts(const fixel::DesignResult& a, const fixel::DesignResult& b) {
  bool same = a.layouts.size() == b.layouts.size();
  for (std::size_t k = 0; same && k < a.layouts.size(); ++k)
    same = a.layouts[k].fixels == b.layouts[k].fixels && a.layouts[k].score == b.layouts[k].score;
  return same;
}

// The bounded search against scoring every triple, alternated three times.
int compare_bound(const std::string& name, const fixel::Scene& part, const std::vector<fixel::DesignCandidate>& c,
                  fixel::DesignOptions o, int jobs, const std::string& resolution) {
  o.jobs = jobs;
  std::vector<double> bounded_s, every_s;
  fixel::DesignResult bounded, every;
  for (int run = 0; run < 3; ++run) {
    o.bound = true;
    bounded = fixel::design(part, c, o);
    bounded_s.push_back(bounded.stats.seconds);
    o.bound = false;
    every = fixel::design(part, c, o);
    every_s.push_back(every.stats.seconds);
  }
  std::sort(bounded_s.begin(), bounded_s.end());
  std::sort(every_s.begin(), every_s.end());
  const auto& s = bounded.stats;
  std::cout << name << ": " << c.size() << " candidates, " << s.triples << " triples, top " << o.top << ", resolution "
            << resolution << ", " << jobs << " threads\n"
            << std::fixed << std::setprecision(3) << "bounded: median " << bounded_s[1] << " s (" << bounded_s[0] << "–"
            << bounded_s[2] << "); scored " << s.no_form_closure + s.j_empty + s.regions << ", never scored "
            << s.bounded << ", singular " << s.singular << "\n"
            << "every triple: median " << every_s[1] << " s (" << every_s[0] << "–" << every_s[2] << "); scored "
            << every.stats.no_form_closure + every.stats.j_empty + every.stats.regions << "\n"
            << std::setprecision(2) << "speedup (ratio of the medians): " << every_s[1] / bounded_s[1] << "\n";
  const bool same = same_layouts(bounded, every);
  std::cout << "same layouts: " << (same ? "yes" : "NO") << "\n";
  return same ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::string part_name = "polygon", resolution = "1/256";
  int n = 16, jobs = 2, top = 5;
  bool want_stages = false, want_parts = false, want_bound = false;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::cerr << a << " needs a value\n";
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--part")
      part_name = next();
    else if (a == "--candidates")
      n = fixel::bench::study_count(a.c_str(), next().c_str(), 3);  // a layout is a triple
    else if (a == "--resolution")
      resolution = next();
    else if (a == "--jobs")
      jobs = static_cast<int>(fixel::bench::study_int(a.c_str(), next().c_str(), 0, 256));
    else if (a == "--top")
      top = fixel::bench::study_count(a.c_str(), next().c_str());
    else if (a == "--stages")
      want_stages = true;
    else if (a == "--parts")
      want_parts = true;
    else if (a == "--bound")
      want_bound = true;
    else {
      std::cerr << "usage: design_bench [--part NAME] [--candidates N] [--resolution R] [--jobs J] [--top K] "
                   "[--stages] [--parts] [--bound]\n";
      return 2;
    }
  }
  try {
    fixel::DesignOptions o;
    o.resolution = fixel::parse_rational(resolution, "--resolution");
    o.top = top;
    if (want_parts) {
      // Best layout (n of the 24 default boundary candidates) against the shipped layout, same μ.
      std::cout << "| part | candidates | triples | kept | best sustained | best one-step | shipped sustained | "
                   "shipped one-step | seconds ("
                << jobs << " threads) |\n|---|---|---|---|---|---|---|---|---|\n";
      for (const char* name : {"polygon", "example2_rounded", "blob", "blob32", "fig6", "nonunique_part"}) {
        const fixel::Scene part = bundled(name);
        fixel::DesignOptions p = o;
        p.jobs = jobs;
        p.mu = part.fixels.at(0).mu_upper();
        for (const auto& f : part.fixels) p.mu = std::max(p.mu, f.mu_upper());
        p.pusher_mu = part.pusher_mu_upper();
        const auto c = candidates(part, n);
        const auto r = fixel::design(part, c, p);
        auto pct = [](const std::optional<fixel::Rational>& q) {
          std::ostringstream s;
          if (q)
            s << std::fixed << std::setprecision(1) << 100 * fixel::to_double(*q) << "%";
          else
            s << "–";
          return s.str();
        };
        std::string shipped_s = "error", shipped_t = "error";
        try {
          const auto sh = fixel::score_scene_layout(part, p);
          shipped_s = pct(sh.sustained_score) + (sh.sustained_empty.value_or(false) ? " (J empty)" : "");
          shipped_t = pct(sh.step_score);
          if (!sh.note.empty()) shipped_s += " [" + sh.note + "]";
        } catch (const fixel::Error& e) {
          shipped_s = std::string("error: ") + e.what();
        }
        std::cout << "| " << name << " (mu " << fixel::to_string(p.mu) << ") | " << r.stats.candidates << " | "
                  << r.stats.triples << " | " << r.stats.regions << " | "
                  << (r.layouts.empty() ? "–" : pct(r.layouts[0].sustained_score)) << " | "
                  << (r.layouts.empty() ? "–" : pct(r.layouts[0].step_score)) << " | " << shipped_s << " | "
                  << shipped_t << " | " << std::setprecision(3) << r.stats.seconds << " |\n";
      }
      return 0;
    }
    const fixel::Scene part = bundled(part_name);
    const auto c = candidates(part, n);
    if (want_stages) {
      stages(part, c, o);
      return 0;
    }
    if (want_bound) return compare_bound(part_name, part, c, o, jobs, resolution);
    o.bound = false;  // layouts scored per second: every triple
    o.jobs = 1;
    const auto one = fixel::design(part, c, o);
    o.jobs = jobs;
    const auto many = fixel::design(part, c, o);
    const double per1 = one.stats.triples / one.stats.seconds, perN = many.stats.triples / many.stats.seconds;
    std::cout << part_name << ": " << c.size() << " candidates, " << one.stats.triples << " triples ("
              << one.stats.singular << " singular, " << one.stats.no_form_closure << " without form closure, "
              << one.stats.j_empty << " J empty, " << one.stats.regions << " regions), resolution " << resolution
              << "\n";
    std::cout << std::fixed << std::setprecision(2) << "1 thread: " << one.stats.seconds << " s, " << per1
              << " layouts/s\n"
              << jobs << " threads: " << many.stats.seconds << " s, " << perN << " layouts/s, speedup "
              << one.stats.seconds / many.stats.seconds << "\n";
    const bool same = same_layouts(one, many);
    std::cout << "same ranking: " << (same ? "yes" : "NO") << "\n";
    return same ? 0 : 1;
  } catch (const fixel::Error& e) {
    std::cerr << "design_bench: " << e.what() << "\n";
    return 2;
  }
}
