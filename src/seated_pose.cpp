#include "fixel/seated_pose.h"

#include <cmath>

#include "fixel/error.h"

namespace fixel {

std::string QuadraticIrrational::text() const {
  if (b == 0) return to_string(a);
  return to_string(a) + (b > 0 ? "+" : "") + to_string(b) + "*sqrt(" + to_string(d) + ")";
}

double QuadraticIrrational::approx() const { return to_double(a) + to_double(b) * std::sqrt(to_double(d)); }

SeatedPose seated_pose(const Scene& scene) {
  // Placeholder until the solver lands: only the all-gaps-zero case.
  for (const auto& f : scene.fixels)
    if (f.gap != 0) throw UnsupportedError("fixels", "", "seated pose with open gaps is not implemented yet");
  SeatedPose q;
  q.at_scene_pose = true;
  q.exact = std::array<QuadraticIrrational, 4>{QuadraticIrrational{0, 0, 1}, QuadraticIrrational{0, 0, 1},
                                               QuadraticIrrational{1, 0, 1}, QuadraticIrrational{0, 0, 1}};
  return q;
}

}  // namespace fixel
