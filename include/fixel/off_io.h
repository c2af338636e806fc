#pragma once
/// @file
/// OFF output of bounded polytopes (S clipped to a box, cones, ...).

#include <ostream>
#include <string>
#include <vector>

#include "fixel/cone.h"
#include "fixel/seating.h"

namespace fixel {

/// An axis-aligned box [lo, hi] (exact).
struct Box {
  VectorQ lo, hi;
  /// The box as 2·dim half-spaces.
  std::vector<Halfspace> halfspaces() const;
  /// "[lo0, hi0] x [lo1, hi1] x ..." with exact numbers.
  std::string describe() const;
};

/// The smallest box holding the apex of S and apex + length·r for every ray
/// r of S. Throws InputError if length <= 0.
Box seating_dump_box(const SeatingSet& S, const Rational& length);

/// Exact vertices of the bounded polytope ∩ halfspaces in R^dim (dim 2 or
/// 3), without duplicates. Empty if the intersection is empty.
std::vector<VectorQ> polytope_vertices(const std::vector<Halfspace>& halfspaces, int dim);

/// Writes ∩ halfspaces (which must be bounded, e.g. include a box) as a
/// standard OFF surface: a triangulated convex hull for dim 3, one polygon at
/// z = 0 for dim 2 (a lower-dimensional polytope: its vertices, no faces).
/// Nothing but the "OFF" line, the counts, the vertices and the faces is
/// written, no comments: `fixel dump` puts the metadata in a JSON file beside
/// it (docs/formats.md). Vertex coordinates are rounded to double for
/// display. Returns the number of vertices written (0 for an empty polytope,
/// which writes an empty OFF).
std::size_t write_polytope_off(std::ostream& out, const std::vector<Halfspace>& halfspaces, int dim);

}  // namespace fixel
