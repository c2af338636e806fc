#include "fixel/geometry.h"

#include <string>

#include "fixel/error.h"

namespace fixel {

VectorQ contact_wrench(const Vec2& r_A, const Vec2& d_A, int dof) {
  if (dof != 2 && dof != 3)
    throw InputError("dof", std::to_string(dof), "must be 2 (point mass) or 3 (planar rigid body)");
  VectorQ w(dof);
  w[0] = d_A.x;
  w[1] = d_A.y;
  if (dof == 3) w[2] = cross(r_A, d_A);
  return w;
}

}  // namespace fixel
