// The S/G slice picture (fixel seat --guaranteed --svg).
#include <algorithm>
#include <fstream>
#include <sstream>

#include "fixel/error.h"
#include "fixel/internal/file_write.h"
#include "fixel/internal/seating_sets_check.h"
#include "fixel/svg.h"

namespace fixel {

Rational default_slice_theta(const SeatingSet& S) {
  if (S.dof != 3) throw InputError("S.dof", std::to_string(S.dof), "is a point mass's: the S/G picture needs dof 3");
  Rational theta = S.apex[2];
  for (const auto& r : S.rays) theta += r[2];
  return theta;
}

void write_guaranteed_svg(const std::string& path, const Scene& scene, const SeatingSet& S, const GuaranteedSet* G,
                          const Rational& theta, const std::optional<VectorQ>& impulse) {
  if (S.dof != 3) throw InputError("S.dof", std::to_string(S.dof), "is a point mass's: the S/G picture needs dof 3");
  internal::check_seating_sets_of(scene, S, G);
  // The window: the apex, the tips apex + 2 r of every ray, and where each
  // ray's line meets the slice (apex + t r with t > 0), in (px, py).
  Rational x0 = S.apex[0], x1 = S.apex[0], y0 = S.apex[1], y1 = S.apex[1];
  auto grow = [&](const VectorQ& p) {
    x0 = std::min(x0, Rational(p[0])), x1 = std::max(x1, Rational(p[0]));
    y0 = std::min(y0, Rational(p[1])), y1 = std::max(y1, Rational(p[1]));
  };
  for (const auto& r : S.rays) {
    grow(S.apex + 2 * r);
    if (r[2] != 0 && (theta - S.apex[2]) / r[2] > 0) grow(S.apex + (theta - S.apex[2]) / r[2] * r);
  }
  if (impulse) {
    x0 = std::min(x0, Rational((*impulse)[0])), x1 = std::max(x1, Rational((*impulse)[0]));
    y0 = std::min(y0, Rational((*impulse)[1])), y1 = std::max(y1, Rational((*impulse)[1]));
  }
  const Rational span = std::max(x1 - x0, y1 - y0) * Rational(6, 5) + Rational(1, 100);
  const Rational cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const int n = 120;
  const double size = 480, left = 40, top = 70;
  long in_g = 0, lost = 0;
  std::ostringstream svg;
  svg.precision(4);
  const double width = size + 2 * left + 260, height = size + top + 80;
  svg << "<svg xmlns='http://www.w3.org/2000/svg' width='" << width << "' height='" << height << "' viewBox='0 0 "
      << width << " " << height
      << "' font-family='sans-serif' font-size='13'>\n<rect width='100%' height='100%' fill='white'/>\n";
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      VectorQ p(3);
      p << cx - span / 2 + span * Rational(2 * i + 1, 2 * n), cy + span / 2 - span * Rational(2 * j + 1, 2 * n), theta;
      const bool s = S.contains(p), g = s && G && G->contains(p, S);
      if (!s) continue;
      (g ? in_g : lost)++;
      svg << "<rect x='" << left + i * size / n << "' y='" << top + j * size / n << "' width='" << size / n + 0.3
          << "' height='" << size / n + 0.3 << "' fill='"
          << (!G  ? "#74add1"
              : g ? "#1a9850"
                  : "#d73027")
          << "'/>\n";
    }
  auto mark = [&](const VectorQ& p, const char* label, const char* colour) {
    const double x = left + to_double((p[0] - (cx - span / 2)) / span) * size;
    const double y = top + to_double(((cy + span / 2) - p[1]) / span) * size;
    svg << "<circle cx='" << x << "' cy='" << y << "' r='5' fill='none' stroke='" << colour
        << "' stroke-width='2'/><text x='" << x + 8 << "' y='" << y - 6 << "' fill='" << colour << "'>" << label
        << "</text>\n";
  };
  if (S.apex[2] == theta) mark(S.apex, "apex", "black");
  if (impulse && (*impulse)[2] == theta) mark(*impulse, "p", "black");
  svg << "<rect x='" << left << "' y='" << top << "' width='" << size << "' height='" << size
      << "' fill='none' stroke='#999'/>\n<text x='" << left << "' y='24' font-size='16' font-weight='bold'>"
      << (G ? "seating set S and guaranteed set G: " : "seating set S (one-step: can seat): ") << scene.name
      << "</text>\n<text x='" << left << "' y='44'>slice p_theta = " << to_string(theta) << ", p_x in ["
      << to_double(cx - span / 2) << ", " << to_double(cx + span / 2) << "], p_y in [" << to_double(cy - span / 2)
      << ", " << to_double(cy + span / 2) << "] (N*s)</text>\n";
  const double ly = top + size + 28;
  if (!G) {
    svg << "<rect x='" << left << "' y='" << ly - 10 << "' width='14' height='10' fill='#74add1'/><text x='"
        << left + 20 << "' y='" << ly << "'>in S: one-step: can seat (" << lost << " cells)</text>\n<text x='" << left
        << "' y='" << ly + 22
        << "'>white: outside S. Each cell's centre is decided exactly (--guaranteed adds G).</text>\n</svg>\n";
  } else {
    svg << "<rect x='" << left << "' y='" << ly - 10 << "' width='14' height='10' fill='#1a9850'/><text x='"
        << left + 20 << "' y='" << ly << "'>in G: one-step: guaranteed (" << in_g << " cells)</text>\n<rect x='"
        << left + 330 << "' y='" << ly - 10 << "' width='14' height='10' fill='#d73027'/><text x='" << left + 350
        << "' y='" << ly << "'>in S, not in G (" << lost << " cells)</text>\n<text x='" << left << "' y='" << ly + 22
        << "'>white: outside S. Each cell's centre is decided exactly; " << G->pieces.size()
        << (G->pieces.size() == 1 ? " piece, " : " pieces, ") << G->non_seating.size()
        << " non-seating sets meet S.</text>\n</svg>\n";
  }
  internal::write_file(path, "svg(path)", [&](std::ostream& out) { out << svg.str(); });
}

}  // namespace fixel
