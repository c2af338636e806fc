#pragma once
// The polyline edge a fixel touches (seated_pose.cpp defines it; the seated
// pose and J′'s two-contact families read it).

#include <optional>

#include "fixel/geometry.h"
#include "fixel/scene.h"

namespace fixel::internal {

struct PolylineEdge {
  int piece = -1;
  Vec2 a, b;        // endpoints, frame B
  Vec2 inward;      // rot90(b − a): the interior is on the left of a CCW loop
  Rational u0, du;  // curve parameter of a, and of b minus a
};

// The polyline edge through p: exact collinearity and betweenness. At a
// vertex the edge whose inward normal points along n is preferred.
std::optional<PolylineEdge> polyline_edge_through(const Boundary& boundary, const Vec2& p, const Vec2& n);

}  // namespace fixel::internal
