// [a]x, the matrix of the cross product: a x b = [a]x b. Used by the
// analytic Jacobians (contact_jacobian.h, guidance_jacobian.h, rigid_body_jacobian.h).
#pragma once

#include <Eigen/Core>

namespace vahf {

inline Eigen::Matrix3d CrossMatrix(const Eigen::Vector3d& a) {
  Eigen::Matrix3d m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

}  // namespace vahf
