#include "fixel/geometry.h"

namespace fixel {

VectorQ contact_wrench(const Vec2& r_A, const Vec2& d_A, int dof) {
  VectorQ w(dof);
  w[0] = d_A.x;
  w[1] = d_A.y;
  if (dof == 3) w[2] = cross(r_A, d_A);
  return w;
}

}  // namespace fixel
