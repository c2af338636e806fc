#pragma once
// What the files of the pushing-region picture share (svg_region.cpp: the
// page, legend and shading; svg_region_part.cpp: the left panel, the part;
// svg_region_wrench.cpp: the right panel, wrench directions). Display only:
// doubles.

#include <array>
#include <functional>
#include <optional>
#include <ostream>
#include <utility>

#include "fixel/region.h"
#include "fixel/scene.h"

namespace fixel::internal::region_svg {

inline constexpr double kPanel = 520, kMargin = 40, kHeight = 600;
inline const char* colour(RegionStatus s) {
  return s == RegionStatus::kIn ? "#1a9850" : s == RegionStatus::kOut ? "#bdbdbd" : "#fdae61";
}

inline double d(const Rational& q) { return to_double(q); }

// What differs between the pictures of the push models.
struct Picture {
  const char* in_label;
  const char* shade_caption;
  // 0: not shaded, 1: reaches the target, 2: held by a jam cone (display grid).
  std::function<int(double, double, double)> shade;
  std::optional<std::array<double, 3>> ghost;  // seated pose (x, y, θ) to draw as a ghost outline
  const char* push_caption = nullptr;
  const char* partial_label = "partial (undecided at the resolution)";
};

// The ends to draw: an exact (algebraic) end refined to width 10^-9 of the
// curve parameter, then its midpoint (display only).
std::pair<Rational, Rational> drawn_ends(const RegionInterval& r);

// Left panel: the outline coloured by status, axes and scale bar, curve
// labels, push arrows, fixels, the ghost at q* and the centre of mass.
void draw_part_panel(std::ostream& svg, const Scene& scene, const Region& region, const Picture& pic);

// Right panel: wrench directions on the unit sphere.
void draw_wrench_panel(std::ostream& svg, const Scene& scene, const Region& region, const Picture& pic);

}  // namespace fixel::internal::region_svg
