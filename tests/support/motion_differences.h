// Central differences with respect to a rigid motion, in the columns of the
// analytic Jacobians (contact_model.h's ContactJacobian): (dx, dtheta, v, w),
// a translation, a world rotation about the origin (R -> exp([dtheta]x) R),
// the velocity and the angular velocity; and a block-wise comparison whose
// tolerance is relative to each 3 x 3 block, so that a wrong sign or a
// missing term in any block fails.
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "vahf/contact/contact_model.h"

namespace vahf::testing {

// m moved by e along column `column` (0-11).
inline contact::RigidMotion Moved(contact::RigidMotion m, int column, double e) {
  const int axis = column % 3;
  const Eigen::Vector3d step = e * Eigen::Vector3d::Unit(axis);
  switch (column / 3) {
    case 0:
      m.pose.translation() += step;
      break;
    case 1:
      m.pose.linear() =
          Eigen::AngleAxisd(e, Eigen::Vector3d::Unit(axis)).toRotationMatrix() *
          m.pose.linear();
      break;
    case 2:
      m.velocity += step;
      break;
    default:
      m.angular_velocity += step;
      break;
  }
  return m;
}

// d f / d(motion) by central differences, steps h per column group.
template <class F>
Eigen::MatrixXd MotionDifferences(const F& f, const contact::RigidMotion& m,
                                  const std::array<double, 4>& h) {
  const Eigen::VectorXd at = f(m);
  Eigen::MatrixXd out(at.size(), 12);
  for (int j = 0; j < 12; ++j) {
    const double e = h[j / 3];
    const contact::RigidMotion up = Moved(m, j, e), down = Moved(m, j, -e);
    // The step as represented: 0.93 m + 1e-12 m is not 1e-12 more.
    double step = 2 * e;
    if (j < 3) step = up.pose.translation()[j] - down.pose.translation()[j];
    if (j >= 6)
      step = j < 9 ? up.velocity[j - 6] - down.velocity[j - 6]
                   : up.angular_velocity[j - 9] - down.angular_velocity[j - 9];
    out.col(j) = (f(up) - f(down)) / step;
  }
  return out;
}

// Every block of `analytic` (rows and columns cut into the given segments)
// within rel of the same block of `reference`, plus `floor` times the largest
// block of its column segment (for blocks that vanish but for the
// differences' noise). The worst error against its allowance is reported.
inline ::testing::AssertionResult BlocksAgree(const Eigen::MatrixXd& analytic,
                                              const Eigen::MatrixXd& reference,
                                              double rel, double floor,
                                              const std::vector<int>& rows,
                                              const std::vector<int>& cols) {
  if (analytic.rows() != reference.rows() || analytic.cols() != reference.cols())
    return ::testing::AssertionFailure() << "sizes differ";
  std::string failures;
  double worst = 0;
  for (int c = 0, j = 0; j < static_cast<int>(cols.size()); c += cols[j++]) {
    double group = 0;
    for (int r = 0, i = 0; i < static_cast<int>(rows.size()); r += rows[i++])
      group = std::max(group, reference.block(r, c, rows[i], cols[j]).norm());
    for (int r = 0, i = 0; i < static_cast<int>(rows.size()); r += rows[i++]) {
      const double size = reference.block(r, c, rows[i], cols[j]).norm();
      const double error = (analytic.block(r, c, rows[i], cols[j]) -
                            reference.block(r, c, rows[i], cols[j]))
                               .norm();
      const double allowed = rel * size + floor * group;
      if (allowed > 0) worst = std::max(worst, error / allowed);
      if (error > allowed)
        failures += "\n  block at (" + std::to_string(r) + ", " + std::to_string(c) +
                    "): error " + std::to_string(error) + " of " + std::to_string(size);
    }
  }
  if (failures.empty())
    return ::testing::AssertionSuccess() << "worst error/allowed " << worst;
  return ::testing::AssertionFailure() << "blocks differ (worst error/allowed " << worst
                                       << "):" << failures << "\nanalytic:\n"
                                       << analytic << "\nreference:\n"
                                       << reference;
}

// The same with 3 x 3 blocks.
inline ::testing::AssertionResult BlocksAgree(const Eigen::MatrixXd& analytic,
                                              const Eigen::MatrixXd& reference,
                                              double rel, double floor = 1e-8) {
  const auto threes = [](Eigen::Index n) {
    std::vector<int> out(static_cast<std::size_t>((n + 2) / 3), 3);
    if (n % 3) out.back() = static_cast<int>(n % 3);
    return out;
  };
  return BlocksAgree(analytic, reference, rel, floor, threes(reference.rows()),
                     threes(reference.cols()));
}

}  // namespace vahf::testing
