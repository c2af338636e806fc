// The pushing-region pictures (fixel region --svg): one function per panel.
#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <functional>
#include <map>
#include <sstream>

#include "fixel/error.h"
#include "fixel/internal/readable.h"
#include "fixel/svg.h"
#include "fixel/wrench_cone.h"

namespace fixel {

namespace {

constexpr double kPanel = 520, kMargin = 40, kHeight = 600;
const char* colour(RegionStatus s) {
  return s == RegionStatus::kIn ? "#1a9850" : s == RegionStatus::kOut ? "#bdbdbd" : "#fdae61";
}

struct Frame {  // body frame → left panel pixels
  double cx, cy, scale;
  double x(double v) const { return kMargin + kPanel / 2 + (v - cx) * scale; }
  double y(double v) const { return kMargin + 50 + kPanel / 2 - (v - cy) * scale; }
};

double d(const Rational& q) { return to_double(q); }

// Longitude/latitude (degrees) of a wrench direction (fx, fy, m): longitude
// is the push direction, latitude atan(m / |f|) the signed lever of the
// line of action about the centre of mass.
std::pair<double, double> lonlat(double fx, double fy, double m) {
  return {std::atan2(fy, fx) * 180 / M_PI, std::atan2(m, std::hypot(fx, fy)) * 180 / M_PI};
}
double px(double lon) { return kPanel + 2 * kMargin + 20 + (lon + 180) / 360 * kPanel; }
double py(double lat) { return kMargin + 50 + kPanel / 4 + (90 - lat) / 180 * kPanel / 2; }  // equal-angle scale

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

// What differs between the pictures of the push models.
struct Picture {
  const char* in_label;
  const char* shade_caption;
  // 0: not shaded, 1: reaches the target, 2: held by a jam cone (display grid).
  std::function<int(double, double, double)> shade;
  std::optional<std::array<double, 3>> ghost;  // seated pose (x, y, θ) to draw as a ghost outline
  const char* push_caption = nullptr;
};

// The left panel's frame: fits the outline and the fixels; `span` is the
// fitted width in metres.
Frame fit_frame(const Scene& scene, double& span) {
  const Boundary& b = *scene.body.boundary;
  // Fit the outline and the fixels.
  double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
  auto grow = [&](double x, double y) {
    xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
  };
  for (const auto& piece : b.pieces)
    for (int k = 0; k <= 16; ++k) {
      const Vec2 p = piece.point(Rational(k, 16));
      grow(d(p.x), d(p.y));
    }
  for (const auto& f : scene.fixels) grow(d(f.p_AoF_A.x), d(f.p_AoF_A.y));
  span = std::max(xmax - xmin, ymax - ymin) * 1.25 + 1e-9;
  return Frame{(xmin + xmax) / 2, (ymin + ymax) / 2, kPanel / span};
}

void draw_legend(std::ostream& svg, const Scene& scene, const Region& region, const std::string& method,
                 const Picture& pic) {
  std::map<RegionStatus, int> counts;
  for (const auto& r : region.intervals) ++counts[r.status];
  svg << "<text x='" << kMargin << "' y='24' font-size='16' font-weight='bold'>fixel pushing region: " << scene.name
      << "</text>\n<text x='" << kMargin << "' y='44'>cone " << method << ", resolution "
      << (region.resolution ? to_string(*region.resolution) : "none") << ", pusher mu " << to_string(region.pusher_mu)
      << ", intervals: " << counts[RegionStatus::kIn] << " in, " << counts[RegionStatus::kPartial] << " partial, "
      << counts[RegionStatus::kOut] << " out; " << region.stats.cone_tests << " cone tests</text>\n";
  if (pic.push_caption) svg << "<text x='" << kMargin << "' y='62'>" << pic.push_caption << "</text>\n";
  const double ly = kHeight + 60;
  const std::pair<RegionStatus, const char*> keys[] = {
      {RegionStatus::kIn, pic.in_label},
      {RegionStatus::kPartial, "partial (undecided at the resolution)"},
      {RegionStatus::kOut, "out"}};
  double lx = kMargin;
  for (const auto& [status, label] : keys) {
    svg << "<rect x='" << lx << "' y='" << ly - 11 << "' width='24' height='8' fill='" << colour(status) << "'/>"
        << "<text x='" << lx + 30 << "' y='" << ly - 3 << "'>" << label << "</text>\n";
    lx += 40 + 7.2 * std::string(label).size();
  }
  svg << "<text x='" << kMargin << "' y='" << ly + 16
      << "'>+ centre of mass; blue: fixels with inward normal and friction cone (dashed)</text>\n";
}

// Left panel: the outline coloured by status.
void draw_outline_panel(std::ostream& svg, const Frame& F, const Boundary& b, const Region& region) {
  svg << "<rect x='" << kMargin << "' y='" << kMargin + 50 << "' width='" << kPanel << "' height='" << kPanel
      << "' fill='none' stroke='#ddd'/>\n";
  // Out first, then in, then partial: an undecided stretch is never hidden under another colour.
  std::vector<const RegionInterval*> order;
  for (RegionStatus s : {RegionStatus::kOut, RegionStatus::kIn, RegionStatus::kPartial})
    for (const auto& r : region.intervals)
      if (r.status == s) order.push_back(&r);
  for (const RegionInterval* rp : order) {
    const RegionInterval& r = *rp;
    for (const auto& piece : b.pieces) {
      if (piece.curve != r.curve || piece.u1 < r.u0 || piece.u0 > r.u1) continue;
      const Rational a = std::max(piece.u0, r.u0), e = std::min(piece.u1, r.u1);
      if (a == e) {  // a corner point
        const Vec2 p = piece.point(piece.local(a));
        svg << "<circle cx='" << F.x(d(p.x)) << "' cy='" << F.y(d(p.y)) << "' r='5' fill='" << colour(r.status)
            << "' stroke='black' stroke-width='0.5'/>\n";
        continue;
      }
      svg << "<polyline fill='none' stroke-width='6' stroke-linecap='round' stroke='" << colour(r.status)
          << "' points='";
      for (int k = 0; k <= 24; ++k) {
        const Vec2 p = piece.point(piece.local(a + (e - a) * Rational(k, 24)));
        svg << F.x(d(p.x)) << "," << F.y(d(p.y)) << " ";
      }
      svg << "'/>\n";
    }
  }
}

// Axes of frame A through its origin (when in view) and a scale bar of a
// round length, so that distances can be read off the picture.
void draw_axes_and_scale(std::ostream& svg, const Frame& F, double span) {
  const double left = kMargin, top = kMargin + 50, right = kMargin + kPanel, bottom = kMargin + 50 + kPanel;
  svg << "<g id='axes' stroke='#999' stroke-width='0.8'>";
  const double ox = F.x(0), oy = F.y(0);
  if (ox > left && ox < right)
    svg << "<line x1='" << ox << "' y1='" << bottom << "' x2='" << ox << "' y2='" << top << "'/>";
  if (oy > top && oy < bottom)
    svg << "<line x1='" << left << "' y1='" << oy << "' x2='" << right << "' y2='" << oy << "'/>";
  svg << "</g>\n<text x='" << right - 12 << "' y='" << (oy > top && oy < bottom ? oy - 4 : bottom - 4)
      << "' fill='#666'>x</text><text x='" << (ox > left && ox < right ? ox + 4 : left + 4) << "' y='" << top + 12
      << "' fill='#666'>y</text>\n";
  // A 1, 2 or 5 times 10^k length of at most a quarter of the panel.
  double bar = std::pow(10.0, std::floor(std::log10(span / 4)));
  for (double m : {5.0, 2.0})
    if (bar * m <= span / 4) {
      bar *= m;
      break;
    }
  const double x0 = left + 12, y0 = bottom - 14, w = bar * F.scale;
  svg << "<g id='scale-bar'><line x1='" << x0 << "' y1='" << y0 << "' x2='" << x0 + w << "' y2='" << y0
      << "' stroke='black' stroke-width='2'/><line x1='" << x0 << "' y1='" << y0 - 4 << "' x2='" << x0 << "' y2='"
      << y0 + 4 << "' stroke='black'/><line x1='" << x0 + w << "' y1='" << y0 - 4 << "' x2='" << x0 + w << "' y2='"
      << y0 + 4 << "' stroke='black'/><text x='" << x0 << "' y='" << y0 - 6 << "'>" << internal::decimal(bar, 3)
      << " m</text></g>\n";
}

// Each curve's number at its start point.
void draw_curve_labels(std::ostream& svg, const Frame& F, const Boundary& b) {
  for (std::size_t k = 0; k < b.curves.size(); ++k) {
    const Vec2 p = b.curves[k].point(b.curves[k].u_begin());
    svg << "<text class='curve-label' x='" << F.x(d(p.x)) + 5 << "' y='" << F.y(d(p.y)) - 5
        << "' fill='#555' font-size='11'>curve " << k << "</text>\n";
  }
}

// An arrow onto the middle of every IN stretch, along the push direction.
void draw_push_arrows(std::ostream& svg, const Frame& F, const Region& region, double length) {
  for (std::size_t k = 0; k < region.intervals.size() && k < region.places.size(); ++k) {
    const RegionInterval& r = region.intervals[k];
    const IntervalPlace& at = region.places[k];
    if (r.status != RegionStatus::kIn || !at.push_direction_A || r.u0 == r.u1) continue;
    const double mx = (d(at.start_A.x) + d(at.end_A.x)) / 2, my = (d(at.start_A.y) + d(at.end_A.y)) / 2;
    const double dx = (*at.push_direction_A)[0], dy = (*at.push_direction_A)[1];
    const double tx = F.x(mx), ty = F.y(my), sx = F.x(mx - length * dx), sy = F.y(my - length * dy);
    const double ux = (tx - sx) / std::hypot(tx - sx, ty - sy), uy = (ty - sy) / std::hypot(tx - sx, ty - sy);
    svg << "<g class='push-arrow' stroke='#1a9850' fill='#1a9850'><line x1='" << sx << "' y1='" << sy << "' x2='"
        << tx - 6 * ux << "' y2='" << ty - 6 * uy << "' stroke-width='2'/><polygon points='" << tx << "," << ty << " "
        << tx - 9 * ux - 4 * uy << "," << ty - 9 * uy + 4 * ux << " " << tx - 9 * ux + 4 * uy << ","
        << ty - 9 * uy - 4 * ux << "'/></g>\n";
  }
}

// Fixels: point, inward normal, friction cone edges (arrows of length `arrow`).
void draw_fixels(std::ostream& svg, const Frame& F, const Scene& scene, double arrow) {
  for (std::size_t i = 0; i < scene.fixels.size(); ++i) {
    const auto& f = scene.fixels[i];
    const double x = d(f.p_AoF_A.x), y = d(f.p_AoF_A.y), nx = d(f.n_A.x), ny = d(f.n_A.y), mu = d(f.mu);
    for (double s : {-1.0, 1.0}) {
      const double ex = nx - s * mu * ny, ey = ny + s * mu * nx, len = std::hypot(ex, ey);
      svg << "<line x1='" << F.x(x) << "' y1='" << F.y(y) << "' x2='" << F.x(x + arrow * ex / len) << "' y2='"
          << F.y(y + arrow * ey / len) << "' stroke='#6baed6' stroke-dasharray='4,3'/>\n";
    }
    svg << "<line x1='" << F.x(x) << "' y1='" << F.y(y) << "' x2='" << F.x(x + arrow * nx) << "' y2='"
        << F.y(y + arrow * ny) << "' stroke='#08519c' stroke-width='2'/>\n<circle cx='" << F.x(x) << "' cy='" << F.y(y)
        << "' r='4' fill='#08519c'/>\n<text x='" << F.x(x) + 6 << "' y='" << F.y(y) + 14 << "' fill='#08519c'>f" << i
        << "</text>\n";
  }
}

// The part at its seated pose (x, y, θ): rotated about the centre of mass,
// then translated; and where the fixels really are.
void draw_ghost(std::ostream& svg, const Frame& F, const Scene& scene, const std::array<double, 3>& pose) {
  const Boundary& b = *scene.body.boundary;
  const double cx = d(scene.body.p_AoCm_A.x), cy = d(scene.body.p_AoCm_A.y);
  const auto [gx, gy, th] = pose;
  svg << "<polyline fill='none' stroke='#756bb1' stroke-dasharray='6,4' stroke-width='1.5' points='";
  for (const auto& piece : b.pieces)
    for (int k = 0; k <= 16; ++k) {
      const Vec2 p = piece.point(Rational(k, 16));
      const double rx = d(p.x) - cx, ry = d(p.y) - cy;
      svg << F.x(cx + gx + std::cos(th) * rx - std::sin(th) * ry) << ","
          << F.y(cy + gy + std::sin(th) * rx + std::cos(th) * ry) << " ";
    }
  svg << "'/>\n";
  for (const auto& f : scene.fixels) {  // where the fixels really are: f = p − ψ n
    const double fx = d(f.p_AoF_A.x - f.gap * f.n_A.x), fy = d(f.p_AoF_A.y - f.gap * f.n_A.y);
    svg << "<circle cx='" << F.x(fx) << "' cy='" << F.y(fy) << "' r='3' fill='#756bb1'/>\n";
  }
}

// Right panel: wrench directions on the unit sphere.
void draw_wrench_panel(std::ostream& svg, const Scene& scene, const Region& region, const Picture& pic) {
  const Boundary& b = *scene.body.boundary;
  const double cx = d(scene.body.p_AoCm_A.x), cy = d(scene.body.p_AoCm_A.y);
  const double x0 = px(-180), y0 = py(90);
  svg << "<text x='" << x0 << "' y='" << y0 - 8
      << "'>unit wrench directions: longitude = push direction, latitude = "
         "atan(moment / |force|)</text>\n<text x='"
      << x0 << "' y='" << py(-90) + 50 << "'>curve: boundary push wrench by status"
      << (region.pusher_mu > 0 ? " (dashed: friction edges)" : "") << "; outlines: piece cones</text>\n";
  const int nlon = 120, nlat = 60;
  for (int i = 0; i < nlon; ++i)
    for (int j = 0; j < nlat; ++j) {
      const double lon = -180 + (i + 0.5) * 360.0 / nlon, lat = -90 + (j + 0.5) * 180.0 / nlat;
      const double fx = std::cos(lat * M_PI / 180) * std::cos(lon * M_PI / 180),
                   fy = std::cos(lat * M_PI / 180) * std::sin(lon * M_PI / 180), m = std::sin(lat * M_PI / 180);
      const int shade = pic.shade(fx, fy, m);
      if (shade)
        svg << "<rect x='" << px(lon - 180.0 / nlon) << "' y='" << py(lat + 90.0 / nlat) << "' width='"
            << kPanel / nlon + 0.3 << "' height='" << (py(-90) - py(90)) / nlat + 0.3 << "' fill='"
            << (shade == 1 ? "#c6dbef" : "#fdd0a2") << "'/>\n";
    }
  svg << "<rect x='" << x0 << "' y='" << y0 << "' width='" << kPanel << "' height='" << py(-90) - py(90)
      << "' fill='none' stroke='#999'/>\n<text x='" << x0 + 4 << "' y='" << py(-90) + 16 << "' fill='#3182bd'>"
      << pic.shade_caption << "</text>\n";
  // Boundary wrench curves coloured by status: the frictionless normal, or
  // with a frictional pusher both edges of its friction cone (dashed).
  std::vector<EdgeFamily> families = {EdgeFamily::kNormal};
  if (region.pusher_mu > 0) families = {EdgeFamily::kPlus, EdgeFamily::kMinus};
  for (EdgeFamily family : families)
    for (const auto& r : region.intervals)
      for (const auto& piece : b.pieces) {
        if (piece.curve != r.curve || piece.u1 <= r.u0 || piece.u0 >= r.u1) continue;
        const Rational a = std::max(piece.u0, r.u0), e = std::min(piece.u1, r.u1);
        double last_lon = 1e9;
        for (int k = 0; k <= 12; ++k) {
          const Rational s = piece.local(a + (e - a) * Rational(k, 12));
          const Vec2 p = piece.point(s), T = piece.derivative(s);
          if (T.x == 0 && T.y == 0) continue;
          const Vec2 dir = push_direction(T, family, region.pusher_mu);
          const double nx = d(dir.x), ny = d(dir.y), len = std::hypot(nx, ny);
          const double rx = d(p.x) - cx, ry = d(p.y) - cy;
          const auto [lon, lat] = lonlat(nx / len, ny / len, (rx * ny - ry * nx) / len);
          if (std::abs(lon - last_lon) < 180 && last_lon < 1e8)
            svg << " L" << px(lon) << "," << py(lat);
          else
            svg << (last_lon < 1e8 ? "'/>\n" : "") << "<path class='wrench-curve' fill='none' stroke-width='3'"
                << (family == EdgeFamily::kNormal ? "" : " stroke-dasharray='7,3'") << " stroke='" << colour(r.status)
                << "' d='M" << px(lon) << "," << py(lat);
          last_lon = lon;
        }
        if (last_lon < 1e8) svg << "'/>\n";
      }
  // Tight cones of the Bézier pieces (frictionless), as outlines.
  for (const auto& piece : b.pieces) {
    const auto cone = segment_wrench_cone(piece, scene.body.p_AoCm_A, EdgeFamily::kNormal, 0, ConeMethod::kTight);
    if (!cone) continue;
    std::vector<std::pair<double, double>> pts;
    for (int k : {0, 1, 3, 2}) {
      const auto& g = cone->generators[k];
      pts.push_back(lonlat(d(g[0]), d(g[1]), d(g[2])));
    }
    bool wraps = false;
    for (const auto& q : pts) wraps = wraps || std::abs(q.first - pts[0].first) > 180;
    if (wraps) continue;  // skip the few that straddle the ±180° seam
    svg << "<polygon fill='none' stroke='#636363' stroke-width='0.8' points='";
    for (const auto& [lon, lat] : pts) svg << px(lon) << "," << py(lat) << " ";
    svg << "'/>\n";
  }
  for (int lon = -180; lon <= 180; lon += 90)
    svg << "<text x='" << px(lon) - 10 << "' y='" << py(-90) + 32 << "' fill='#666'>" << lon << "°</text>\n";
  for (int lat : {-90, 0, 90})
    svg << "<text x='" << px(-180) - 34 << "' y='" << py(lat) + 4 << "' fill='#666'>" << lat << "°</text>\n";
}

void draw_region(const std::string& path, const Scene& scene, const Region& region, const std::string& method,
                 const Picture& pic) {
  double span = 0;
  const Frame F = fit_frame(scene, span);
  std::ostringstream svg;
  svg.precision(6);
  const double width = 2 * kPanel + 3 * kMargin + 20;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << kHeight + 80
      << "' font-family='sans-serif' font-size='13'>\n<rect width='100%' height='100%' fill='white'/>\n";

  draw_legend(svg, scene, region, method, pic);
  draw_axes_and_scale(svg, F, span);
  draw_outline_panel(svg, F, *scene.body.boundary, region);
  draw_curve_labels(svg, F, *scene.body.boundary);
  draw_push_arrows(svg, F, region, 0.08 * span);
  draw_fixels(svg, F, scene, 0.12 * span);
  if (pic.ghost) draw_ghost(svg, F, scene, *pic.ghost);
  const double cx = d(scene.body.p_AoCm_A.x), cy = d(scene.body.p_AoCm_A.y);
  svg << "<path d='M" << F.x(cx) - 7 << "," << F.y(cy) << " h14 M" << F.x(cx) << "," << F.y(cy) - 7
      << " v14' stroke='black' stroke-width='2'/>\n";

  draw_wrench_panel(svg, scene, region, pic);
  svg << "</svg>\n";

  std::ofstream out(path);
  if (!out) throw InputError("svg(path)", path, "cannot be written");
  out << svg.str();
  if (!out) throw InputError("svg(path)", path, "could not be written completely");
}

}  // namespace

void write_region_svg(const std::string& path, const Scene& scene, const SeatingSet& S, const Region& region,
                      const GuaranteedSet* G) {
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
  pic.in_label = "in: sustained push: seats and stays (J)";
  pic.shade_caption = "blue: directions in J; orange: into the seat, but two fixels can hold it";
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
