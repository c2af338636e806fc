#pragma once
// S, and G when one is given, against the scene a report, file or picture
// is made for: one call for the writers that take an optional G.
#include "fixel/guaranteed.h"

namespace fixel::internal {

inline void check_seating_sets_of(const Scene& scene, const SeatingSet& S, const GuaranteedSet* G) {
  if (G)
    check_guaranteed_set_of(scene, S, *G);
  else
    check_seating_set_of(scene, S);
}

}  // namespace fixel::internal
