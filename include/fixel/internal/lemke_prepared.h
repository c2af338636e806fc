#pragma once
// What a LemkeMatrix caches beside B (include/fixel/lemke.h): the parts of
// the filtered run's first tableaux that depend on B alone.
#include "fixel/internal/lemke_interval.h"
#include "fixel/internal/lemke_scaled.h"
#include "fixel/rational.h"

namespace fixel::internal {

struct PreparedLemkeMatrix {
  MatrixQ B;
  IntervalRows intervals;  // the interval tableau's B part
  ScaledMatrix scaled;     // the exact side's B part
};

}  // namespace fixel::internal
