// Scaling of the pushing region with the boundary: polyline ellipses (semi-
// axes 2 and 1, vertices on the 2^-20 grid) with 1,000 to 64,000 edges, and
// 100,000, each run filtered and with every filter off (--exact-only). Prints
// the times, the filter counters and the exponent of a least-squares fit
// t = c·n^k over 1k–64k edges. A plain program (one run per size):
//   build/bench/scaling_bench [max_edges] [--filtered-only]
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fixel/filter.h"
#include "fixel/region.h"
#include "fixel/scene.h"
#include "fixel/scene_json.h"
#include "fixel/seating.h"
#include "study_args.h"

namespace {

std::string grid(double x) {
  const long long k = std::llround(x * 1048576.0);
  return "\"" + std::to_string(k) + "/1048576\"";
}

// The polygon scene's fixels (data/scenes/polygon.json) against an ellipse.
std::string ellipse_scene(int edges) {
  std::ostringstream s;
  s << R"({"name": "ellipse )" << edges << R"(", "time_step": "1", "body": {"dof": 3, "velocity": ["0", "0", "0"],)"
    << R"( "boundary": [{"type": "polyline", "points": [)";
  for (int k = 0; k <= edges; ++k) {
    const double phi = 2 * M_PI * (k % edges) / edges;
    s << (k ? ", " : "") << "[" << grid(2 * std::cos(phi)) << ", " << grid(std::sin(phi)) << "]";
  }
  s << R"(]}]}, "fixels": [)"
    << R"({"point": ["-2", "0"], "normal": ["1", "0"], "mu": "1/10", "gap": "1/10", "off_boundary": true},)"
    << R"({"point": ["-1/2", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "1/20", "off_boundary": true},)"
    << R"({"point": ["1", "-1"], "normal": ["0", "1"], "mu": "1/10", "gap": "3/20", "off_boundary": true}],)"
    << R"( "pusher": {"mu": "0"}})";
  return s.str();
}

double run(const fixel::Scene& scene, const fixel::SeatingSet& S, bool exact, fixel::Region& r) {
  fixel::ForceExactScope scope(exact);
  const auto t0 = std::chrono::steady_clock::now();
  r = fixel::compute_region(scene, S, fixel::RegionOptions{});
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double fitted_exponent(const std::vector<double>& n, const std::vector<double>& t) {
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  const double m = static_cast<double>(n.size());
  for (std::size_t i = 0; i < n.size(); ++i) {
    const double x = std::log(n[i]), y = std::log(t[i]);
    sx += x, sy += y, sxx += x * x, sxy += x * y;
  }
  return (m * sxy - sx * sy) / (m * sxx - sx * sx);
}

}  // namespace

int main(int argc, char** argv) {
  const char* const usage = "usage: scaling_bench [MAX_EDGES] [--filtered-only]\n";
  for (int i = 1; i < argc; ++i)
    if (std::string(argv[i]) == "--help" || std::string(argv[i]) == "-h") {
      std::cout << usage;
      return 0;
    }
  if (argc > 3 || (argc == 3 && std::string(argv[2]) != "--filtered-only")) {
    std::cerr << usage;
    return 2;
  }
  const int max_edges =
      argc > 1 ? static_cast<int>(fixel::bench::study_int("MAX_EDGES", argv[1], 0, INT32_MAX)) : 100000;
  const bool filtered_only = argc > 2;
  std::vector<double> ns, tf, te;
  std::cout << "edges  filtered s  exact-only s  ratio  cone tests  filter certified/fallbacks  (where)"
               "  (region at resolution 1/1024)\n";
  for (int edges : {1000, 2000, 4000, 8000, 16000, 32000, 64000, 100000}) {
    if (edges > max_edges) break;
    const fixel::Scene scene = fixel::parse_scene(ellipse_scene(edges), "ellipse");
    const fixel::SeatingSet S = fixel::seating_set(scene);
    fixel::Region rf, re;
    fixel::reset_filter_stats();
    const double f = run(scene, S, false, rf);
    const auto st = fixel::filter_stats();
    const double e = filtered_only ? 0 : run(scene, S, true, re);
    if (!filtered_only && rf.intervals.size() != re.intervals.size()) std::cout << "  REGIONS DIFFER\n";
    std::cout << edges << "  " << f << "  " << e << "  " << e / f << "  " << rf.stats.cone_tests << "  "
              << st.total_certified() << "/" << st.total_fallbacks();
    // Where the fallbacks ran, site by site.
    for (int k = 0; k < static_cast<int>(fixel::FilterSite::kCount); ++k) {
      const auto site = static_cast<fixel::FilterSite>(k);
      if (st.at(site).fallbacks > 0) std::cout << "  " << fixel::to_string(site) << " " << st.at(site).fallbacks;
    }
    std::cout << "\n";
    if (edges <= 64000) {
      ns.push_back(edges);
      tf.push_back(f);
      te.push_back(e);
    }
  }
  if (ns.size() >= 2)
    std::cout << "fitted exponent k in t = c n^k over " << ns.front() << "-" << ns.back() << " edges: filtered "
              << fitted_exponent(ns, tf) << ", exact-only " << fitted_exponent(ns, te) << "\n";
  return 0;
}
