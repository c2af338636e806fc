// The pushing-region pictures (fixel region --svg): the page, its legend,
// and what each push model shades; the panels are drawn by
// svg_region_part.cpp and svg_region_wrench.cpp.
#include <array>
#include <cmath>
#include <fstream>
#include <map>
#include <sstream>

#include "fixel/error.h"
#include "fixel/internal/file_write.h"
#include "fixel/internal/scene_differs.h"
#include "fixel/internal/seating_sets_check.h"
#include "fixel/internal/sustained_data.h"
#include "fixel/internal/svg_region.h"
#include "fixel/svg.h"

namespace fixel {

namespace {

using internal::region_svg::colour;
using internal::region_svg::d;
using internal::region_svg::draw_part_panel;
using internal::region_svg::draw_wrench_panel;
using internal::region_svg::kHeight;
using internal::region_svg::kMargin;
using internal::region_svg::kPanel;
using internal::region_svg::Picture;

// Does the ray from b0 along w meet {p : a·p >= c for every row}? Doubles,
// for shading only.
bool hits_display(const std::vector<Halfspace>& rows, const VectorQ& b0, double fx, double fy, double m) {
  double lo = 0, hi = INFINITY;
  for (const auto& h : rows) {
    const double a = d(h.a[0]) * fx + d(h.a[1]) * fy + d(h.a[2]) * m;
    const double b = d(h.c) - (d(h.a[0]) * d(b0[0]) + d(h.a[1]) * d(b0[1]) + d(h.a[2]) * d(b0[2]));
    if (a > 1e-15)
      lo = std::max(lo, b / a);
    else if (a < -1e-15)
      hi = std::min(hi, b / a);
    else if (b > 0)
      return false;
  }
  return lo <= hi;
}

void draw_legend(std::ostream& svg, const Scene& scene, const Region& region, const std::string& method,
                 const Picture& pic) {
  std::map<RegionStatus, int> counts;
  for (const auto& r : region.intervals) ++counts[r.status];
  svg << "<text x='" << kMargin << "' y='24' font-size='16' font-weight='bold'>fixel pushing region: " << scene.name
      << " (target " << region.target << ")</text>\n<text x='" << kMargin << "' y='44'>";
  if (region.exact)  // no cone method, no subdivision: the ends are roots
    svg << "exact region: ends by root isolation (" << region.stats.roots << " roots)";
  else
    svg << "cone " << method << ", resolution "
        << (region.resolution ? to_string(*region.resolution) : std::string("none"));
  svg << ", pusher mu " << to_string(region.pusher_mu) << ", intervals: " << counts[RegionStatus::kIn] << " in, "
      << counts[RegionStatus::kPartial] << " partial, " << counts[RegionStatus::kOut] << " out";
  if (!region.exact) svg << "; " << region.stats.cone_tests << " cone tests";
  svg << "</text>\n";
  if (pic.push_caption) svg << "<text x='" << kMargin << "' y='62'>" << pic.push_caption << "</text>\n";
  const double ly = kHeight + 60;
  const std::pair<RegionStatus, const char*> keys[] = {
      {RegionStatus::kIn, pic.in_label}, {RegionStatus::kPartial, pic.partial_label}, {RegionStatus::kOut, "out"}};
  double lx = kMargin;
  for (const auto& [status, label] : keys) {
    svg << "<rect x='" << lx << "' y='" << ly - 11 << "' width='24' height='8' fill='" << colour(status) << "'/>"
        << "<text x='" << lx + 30 << "' y='" << ly - 3 << "'>" << label << "</text>\n";
    lx += 40 + 7.2 * std::string(label).size();
  }
  svg << "<text x='" << kMargin << "' y='" << ly + 16
      << "'>+ centre of mass; blue: fixels with inward normal and friction cone (dashed)</text>\n";
}

void draw_region(const std::string& path, const Scene& scene, const Region& region, const std::string& method,
                 const Picture& pic) {
  std::ostringstream svg;
  svg.precision(6);
  const double width = 2 * kPanel + 3 * kMargin + 60, height = kHeight + 80;  // room for the longest caption
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height << "' viewBox='0 0 "
      << width << " " << height << "' font-family='sans-serif' font-size='13'>\n"
      << "<rect width='100%' height='100%' fill='white'/>\n";

  draw_legend(svg, scene, region, method, pic);
  draw_part_panel(svg, scene, region, pic);
  draw_wrench_panel(svg, scene, region, pic);
  svg << "</svg>\n";

  internal::write_file(path, "svg(path)", [&](std::ostream& out) { out << svg.str(); });
}

}  // namespace

void write_region_svg(const std::string& path, const Scene& scene, const SeatingSet& S, const Region& region,
                      const GuaranteedSet* G) {
  internal::check_seating_sets_of(scene, S, G);
  internal::check_same_scene(region.built_from.get(), scene, internal::region_reads(region.target), "region");
  Picture pic;
  const VectorQ& b0 = scene.background_impulse;
  if (region.target == "G" && G) {
    pic.in_label = "in: one-step: guaranteed (every one-step outcome seats)";
    pic.shade_caption = "shaded: directions whose ray meets G (b0 + tau w in G, display grid)";
    std::vector<std::vector<Halfspace>> pieces;
    for (const auto& p : G->pieces) {
      pieces.push_back(p.closed);
      for (const auto& h : p.strict) pieces.back().push_back(h);  // the closure, for display
    }
    pic.shade = [pieces, &b0](double fx, double fy, double m) {
      for (const auto& rows : pieces)
        if (hits_display(rows, b0, fx, fy, m)) return 1;
      return 0;
    };
  } else {
    pic.in_label = "in: one-step: can seat (some one-step outcome seats)";
    pic.shade_caption = "shaded: directions whose ray meets S (b0 + tau w in S, display grid)";
    pic.shade = [&](double fx, double fy, double m) { return hits_display(S.halfspaces, b0, fx, fy, m) ? 1 : 0; };
  }
  draw_region(path, scene, region, method_of(region) + (region.target == "G" ? ", against G" : ""), pic);
}

void write_sustained_region_svg(const std::string& path, const Scene& scene, const SustainedSet& J,
                                const Region& region) {
  if (J.data) internal::check_built_from(*J.data, scene, "J");
  internal::check_same_scene(region.built_from.get(), scene, internal::region_reads(region.target), "region");
  // Body-frame wrench w_B → world frame at q* (display only).
  const double th = J.pose.approx[2], c = std::cos(th), s = std::sin(th);
  auto rows = [](const std::vector<std::array<QuadraticIrrational, 3>>& v) {
    std::vector<std::array<double, 3>> out;
    for (const auto& a : v) out.push_back({a[0].approx(), a[1].approx(), a[2].approx()});
    return out;
  };
  auto mids = [](const std::vector<std::array<std::array<double, 2>, 3>>& v) {
    std::vector<std::array<double, 3>> out;
    for (const auto& a : v) out.push_back({(a[0][0] + a[0][1]) / 2, (a[1][0] + a[1][1]) / 2, (a[2][0] + a[2][1]) / 2});
    return out;
  };
  const auto K = J.cone.exact ? rows(J.cone.strict) : mids(J.cone.strict_enclosure);
  std::vector<std::vector<std::array<double, 3>>> jams;
  for (const auto& jam : J.jam_cones)
    jams.push_back(jam.cone.exact ? rows(jam.cone.closed) : mids(jam.cone.closed_enclosure));
  Picture pic;
  const bool approach = region.target == "J'";
  pic.in_label = approach ? "in: sustained push, approach-aware: seats, stays, no pair holds it on the way (J')"
                          : "in: sustained push: seats and stays (J)";
  if (approach) pic.partial_label = "partial (J' not decided by its stand-ins, or at the resolution)";
  pic.shade_caption = approach ? "blue: directions in J (J' is within J, not shaded); orange: two fixels can hold it"
                               : "blue: directions in J; orange: into the seat, but two fixels can hold it";
  pic.push_caption = "push model: sustained (a held wrench, judged at the seated pose q*; dashed: the part at q*)";
  pic.ghost = J.pose.approx;
  pic.shade = [=](double fx, double fy, double m) {
    const double wx = c * fx - s * fy, wy = s * fx + c * fy;
    for (const auto& a : K)
      if (a[0] * wx + a[1] * wy + a[2] * m <= 0) return 0;
    for (const auto& jam : jams) {
      bool in = true;
      for (const auto& a : jam) in = in && a[0] * wx + a[1] * wy + a[2] * m >= 0;
      if (in) return 2;
    }
    return 1;
  };
  draw_region(path, scene, region, method_of(region), pic);
}

}  // namespace fixel
