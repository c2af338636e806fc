// The pushing-region picture's left panel: the part, its outline coloured
// by status, with axes, scale bar, curve labels, push arrows, fixels and
// the ghost at the seated pose (display only).
#include <algorithm>
#include <array>
#include <cmath>

#include "fixel/internal/readable.h"
#include "fixel/internal/svg_region.h"

namespace fixel::internal::region_svg {

namespace {

struct Frame {  // body frame → left panel pixels
  double cx, cy, scale;
  double x(double v) const { return kMargin + kPanel / 2 + (v - cx) * scale; }
  double y(double v) const { return kMargin + 50 + kPanel / 2 - (v - cy) * scale; }
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
    const auto [u0, u1] = drawn_ends(r);
    for (const auto& piece : b.pieces) {
      if (piece.curve != r.curve || piece.u1 < u0 || piece.u0 > u1) continue;
      const Rational a = std::max(piece.u0, u0), e = std::min(piece.u1, u1);
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

// An arrow onto the middle of every IN stretch (the boundary point at its
// middle parameter, where the push direction is taken), along that direction.
void draw_push_arrows(std::ostream& svg, const Frame& F, const Region& region, double length) {
  for (std::size_t k = 0; k < region.intervals.size() && k < region.places.size(); ++k) {
    const RegionInterval& r = region.intervals[k];
    const IntervalPlace& at = region.places[k];
    if (r.status != RegionStatus::kIn || !at.push_direction_A || !at.middle_A || r.u0 == r.u1) continue;
    const double mx = (*at.middle_A)[0], my = (*at.middle_A)[1];
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

}  // namespace

// The ends to draw: an exact (algebraic) end refined to width 10^-9 of the
// curve parameter, then its midpoint (display only).
std::pair<Rational, Rational> drawn_ends(const RegionInterval& r) {
  const Rational w(1, 1000000000);
  return {r.exact_u0 ? refined(*r.exact_u0, w).midpoint() : r.u0,
          r.exact_u1 ? refined(*r.exact_u1, w).midpoint() : r.u1};
}

void draw_part_panel(std::ostream& svg, const Scene& scene, const Region& region, const Picture& pic) {
  double span = 0;
  const Frame F = fit_frame(scene, span);
  draw_axes_and_scale(svg, F, span);
  draw_outline_panel(svg, F, *scene.body.boundary, region);
  draw_curve_labels(svg, F, *scene.body.boundary);
  draw_push_arrows(svg, F, region, 0.08 * span);
  draw_fixels(svg, F, scene, 0.12 * span);
  if (pic.ghost) draw_ghost(svg, F, scene, *pic.ghost);
  const double cx = d(scene.body.p_AoCm_A.x), cy = d(scene.body.p_AoCm_A.y);
  svg << "<path d='M" << F.x(cx) - 7 << "," << F.y(cy) << " h14 M" << F.x(cx) << "," << F.y(cy) - 7
      << " v14' stroke='black' stroke-width='2'/>\n";
}

}  // namespace fixel::internal::region_svg
