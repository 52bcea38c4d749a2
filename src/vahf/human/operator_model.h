// The standing operator: anthropometric landmarks from stature, and the posture
// quantities of Sec. 5.1 (eye, both shoulders, body centre, body plane).
//
// World frame: z up (gravity along -z), metres. The operator stands on the
// floor z = 0 at `position`, facing the horizontal direction `facing_deg`
// (counter-clockwise from +x about +z).
#pragma once

#include <Eigen/Core>
#include <string>

namespace vahf::human {

// Landmark heights and widths as fractions of stature H, from D. A. Winter,
// "Biomechanics and Motor Control of Human Movement", 4th ed., Wiley 2009,
// Fig. 4.1 (segment lengths after Drillis and Contini, 1966).
struct Anthropometry {
  double eye_height = 0.936;       // eye level
  double shoulder_height = 0.818;  // acromion (shoulder joint centre)
  double hip_height = 0.530;       // greater trochanter (hip joint centre)
  double shoulder_width = 0.259;   // biacromial breadth
  // Horizontal offset of the eye ahead of the body plane. Winter's figure gives
  // no sagittal offsets, so vahf keeps the eye in the body plane by default.
  double eye_forward = 0.0;
};

struct Operator {
  double height = 1.75;                                // stature h, m
  double arm_length = 0.74;                            // l, shoulder to fingertip, m
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  // on the floor, m
  double facing_deg = 0.0;          // direction faced, from +x about +z, degrees
  std::string sex = "unspecified";  // a label carried into reports
  Anthropometry proportions;
};

// Where the operator's landmarks are (Sec. 5.1: "sensors mounted on ...
// shoulders and center of body", "the sensor mounted on operator's brow").
struct Posture {
  Eigen::Vector3d eye;
  Eigen::Vector3d left_shoulder;
  Eigen::Vector3d right_shoulder;
  // Centre of the body: the midpoint of the trunk, halfway between the
  // shoulder and hip joint centres on the body's midline.
  Eigen::Vector3d body_centre;
  // The body plane passes through both shoulders and the body centre (Sec. 5.1).
  Eigen::Vector3d forward;  // its unit normal, pointing the way the operator faces
  Eigen::Vector3d down;     // unit, in the plane, from the shoulders to the body centre
};

// An upright standing posture.
Posture StandingPosture(const Operator& op);

// Body plane axes from the three landmarks of Sec. 5.1 (works for any
// posture, not only upright): forward is the normal on the side of `facing`.
void BodyPlaneFrom(const Eigen::Vector3d& left_shoulder,
                   const Eigen::Vector3d& right_shoulder,
                   const Eigen::Vector3d& body_centre, const Eigen::Vector3d& facing,
                   Eigen::Vector3d* forward, Eigen::Vector3d* down);

}  // namespace vahf::human
