#pragma once
// J's data and emptiness without its pieces' extreme rays and its public
// form (sustained.cpp), for ranking many layouts (design.cpp); no CGAL here.
#include <memory>

#include "fixel/scene.h"

namespace fixel {
class RegionTarget;
}

namespace fixel::internal {

struct SustainedData;

// What design's ranking needs of J for each triple: its data (for the region
// against J) and whether it is empty, at about 3/4 of the cost of
// sustained_set, which also makes the public cones and, at an exact seat,
// the pieces' exact extreme rays (read only by J's width, a display
// value; at an enclosed seat the rays are made anyway, since a sign they
// leave open makes the pieces undecided). At an exact seat `data` holds
// only J's first piece, enough to tell that J is not empty. Same
// validation and errors as sustained_set.
struct SustainedCore {
  std::shared_ptr<const SustainedData> data;
  bool empty = false;          // J.empty of sustained_set
  bool pieces_decided = true;  // J.pieces_decided
};
SustainedCore sustained_core(const Scene& scene);

// sustained_target(J) (region_target.h) from J's data alone.
std::unique_ptr<RegionTarget> sustained_target(std::shared_ptr<const SustainedData> data);

// The J′ target (approach_target.cpp): IN questions on `in` (J's rows and
// outer cones of the jam cones swept along the approach), OUT questions on
// `out` (J's rows and jam cones at sampled poses of the approach); with
// `empty`, nothing is IN and everything is OUT.
std::unique_ptr<RegionTarget> sustained_target(std::shared_ptr<const SustainedData> in,
                                               std::shared_ptr<const SustainedData> out, bool empty);

}  // namespace fixel::internal
