// The pushing-region picture's right panel: unit wrench directions on a
// longitude/latitude map, shaded by the target, with the boundary's push
// wrenches coloured by status and the pieces' cones (display only).
#include <cmath>
#include <vector>

#include "fixel/internal/svg_region.h"
#include "fixel/wrench_cone.h"

namespace fixel::internal::region_svg {

namespace {

// Longitude/latitude (degrees) of a wrench direction (fx, fy, m): longitude
// is the push direction, latitude atan(m / |f|) the signed lever of the
// line of action about the centre of mass.
std::pair<double, double> lonlat(double fx, double fy, double m) {
  return {std::atan2(fy, fx) * 180 / M_PI, std::atan2(m, std::hypot(fx, fy)) * 180 / M_PI};
}
double px(double lon) { return kPanel + 2 * kMargin + 20 + (lon + 180) / 360 * kPanel; }
double py(double lat) { return kMargin + 50 + kPanel / 4 + (90 - lat) / 180 * kPanel / 2; }  // equal-angle scale

}  // namespace

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
        const auto [u0, u1] = drawn_ends(r);
        if (piece.curve != r.curve || piece.u1 <= u0 || piece.u0 >= u1) continue;
        const Rational a = std::max(piece.u0, u0), e = std::min(piece.u1, u1);
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
  // Tight cones of the Bézier pieces (frictionless), as outlines. One that
  // straddles the ±180° seam is drawn twice, unwrapped and shifted by 360°,
  // each copy clipped to the panel.
  svg << "<clipPath id='wrench-panel'><rect x='" << px(-180) << "' y='" << py(90) << "' width='" << kPanel
      << "' height='" << py(-90) - py(90) << "'/></clipPath>\n";
  for (const auto& piece : b.pieces) {
    const auto cone = segment_wrench_cone(piece, scene.body.p_AoCm_A, EdgeFamily::kNormal, 0, ConeMethod::kTight);
    if (!cone) continue;
    std::vector<std::pair<double, double>> pts;
    for (int k : {0, 1, 3, 2}) {
      const auto& g = cone->generators[k];
      pts.push_back(lonlat(d(g[0]), d(g[1]), d(g[2])));
    }
    bool wraps = false;
    for (auto& q : pts)
      if (std::abs(q.first - pts[0].first) > 180) {
        q.first += q.first < pts[0].first ? 360 : -360;  // unwrapped next to the first generator
        wraps = true;
      }
    for (const double shift :
         wraps ? std::vector<double>{0, pts[0].first > 0 ? -360.0 : 360.0} : std::vector<double>{0}) {
      svg << "<polygon fill='none' stroke='#636363' stroke-width='0.8'"
          << (wraps ? " clip-path='url(#wrench-panel)'" : "") << " points='";
      for (const auto& [lon, lat] : pts) svg << px(lon + shift) << "," << py(lat) << " ";
      svg << "'/>\n";
    }
  }
  for (int lon = -180; lon <= 180; lon += 90)
    svg << "<text x='" << px(lon) - 10 << "' y='" << py(-90) + 32 << "' fill='#666'>" << lon << "°</text>\n";
  for (int lat : {-90, 0, 90})
    svg << "<text x='" << px(-180) - 34 << "' y='" << py(lat) + 4 << "' fill='#666'>" << lat << "°</text>\n";
}

}  // namespace fixel::internal::region_svg
