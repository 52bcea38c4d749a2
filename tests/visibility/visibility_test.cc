// Visibility V by ray casting (Eq. 1) against closed forms
// (reference/analytic/README.md, "Visibility"):
// - nothing can hide the part: V = 1 exactly with no ray cast; an occluder in
//   view that covers none of it: V = 1 exactly from counted pixels;
// - a part wholly behind a plate: V = 0;
// - a ball behind a plate whose edge crosses the line of sight to the ball's
//   centre: V = 1/2 (the grid and the ball's image are symmetric under a half
//   turn about the view axis, so this one is nearly exact at every N);
// - the same with the edge offset by h = 0.3 of the image disc's radius t:
//   V = 1 - (acos(0.3) - 0.3 sqrt(1 - 0.09)) / pi, the circular segment;
// - a box face-on behind a plate: the image of the near face is a square of
//   half-width (w / 2) / y_near, the plate's edge images at x_e / y_plate
//   (perspective), V = the uncovered fraction;
// - the discretization error of the last two shrinks with N: a bound C / N is
//   asserted at N = 32 ... 512 and the table printed;
// - rotating the scene and the eye together changes V by no more than that;
// - the single-traversal counts equal the literal two passes of Eq. 1, and the
//   same inputs give the same bits.
// Eye at the origin, looking along +y at a part 1 m away.
#include "vahf/visibility/visibility.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>

#include "../geometry/test_shapes.h"
#include "vahf/core/error.h"
#include "vahf/human/operator_model.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::visibility {
namespace {

using Eigen::Isometry3d;
using Eigen::Vector3d;
using geometry::Box;
using geometry::Tessellate;

constexpr double kBallRadius = 0.05;  // m
const Vector3d kEye = Vector3d::Zero();
const Vector3d kPartAt(0, 1, 0);

geometry::TriangleMesh BallMesh() {
  return Tessellate(geometry::testing::Ball(kBallRadius, 128), 1e-4 * kBallRadius);
}

Isometry3d At(const Vector3d& p) {
  Isometry3d x = Isometry3d::Identity();
  x.translation() = p;
  return x;
}

Isometry3d AboutY(double angle) {
  Isometry3d x = Isometry3d::Identity();
  x.linear() = Eigen::AngleAxisd(angle, Vector3d::UnitY()).toRotationMatrix();
  return x;
}

// A 1 m x 1 m plate, 2 mm thick, square to the view axis, its mid-plane at
// y = 0.5. Before the turn about the view axis by `turn` it covers x >= x_edge.
constexpr double kPlateY = 0.5, kPlateHalfThickness = 0.001;
Occluder Plate(double x_edge, double turn) {
  return {Tessellate(Box{{1.0, 2 * kPlateHalfThickness, 1.0}}, 1e-4),
          At({0, kPlateY, 0}) * AboutY(turn) * At({x_edge + 0.5, 0, 0})};
}

// Where a plate edge at x_edge images on the tangent plane: its silhouette is
// the face edge nearest the axis in angle, the far one when x_edge > 0.
double ImageOfEdge(double x_edge) {
  return x_edge /
         (x_edge > 0 ? kPlateY + kPlateHalfThickness : kPlateY - kPlateHalfThickness);
}

// The exact ball's image: a disc of radius t = rho / sqrt(D^2 - rho^2), D = 1.
const double kDisc = kBallRadius / std::sqrt(1.0 - kBallRadius * kBallRadius);

VisibilityResult Cast(const geometry::TriangleMesh& part,
                      const std::vector<Occluder>& occ, const Isometry3d& X_WP, int grid,
                      bool two_pass = false, const Vector3d& eye = kEye) {
  VisibilityCaster caster(part, occ, {grid, two_pass});
  return caster.Compute(eye, X_WP);
}

TEST(Visibility, NothingCanHideCastsNoRay) {
  const auto ball = BallMesh();
  const auto nothing = Cast(ball, {}, At(kPartAt), 128);
  EXPECT_EQ(nothing.path, VisibilityPath::kNothingCanHide);
  EXPECT_EQ(nothing.V, 1.0);
  EXPECT_EQ(nothing.rays_cast, 0);
  // Off to the side (45 degrees from the view axis), and wholly beyond the part.
  const auto side = Cast(ball, {{Tessellate(Box{{0.1, 0.1, 0.1}}, 1e-4), At({1, 1, 0})}},
                         At(kPartAt), 128);
  const auto beyond =
      Cast(ball, {{Tessellate(Box{{0.1, 0.1, 0.1}}, 1e-4), At({0, 1.2, 0})}}, At(kPartAt),
           128);
  for (const auto& r : {side, beyond}) {
    EXPECT_EQ(r.path, VisibilityPath::kNothingCanHide);
    EXPECT_EQ(r.V, 1.0);
    EXPECT_EQ(r.rays_cast, 0);
  }
}

TEST(Visibility, OccluderInViewCoveringNothingGivesExactlyOne) {
  // A large plate just behind the ball: its bounding sphere reaches into the
  // view in front of the ball, so rays are cast, but it hides nothing.
  Occluder behind = Plate(-0.5, 0.0);
  behind.X_WO = At({0, 0.62, 0}) * behind.X_WO;
  for (const bool two_pass : {false, true}) {
    const auto r = Cast(BallMesh(), {behind}, At(kPartAt), 128, two_pass);
    EXPECT_EQ(r.path, VisibilityPath::kRaysCast);
    EXPECT_GT(r.rays_cast, 0);
    EXPECT_GT(r.part_pixels, 10000);  // about pi / 4 of 128^2
    EXPECT_EQ(r.visible_pixels, r.part_pixels);
    EXPECT_EQ(r.V, 1.0);
  }
}

TEST(Visibility, WhollyBehindAPlateGivesZero) {
  for (const bool two_pass : {false, true}) {
    const auto r = Cast(BallMesh(), {Plate(-0.5, 0.0)}, At(kPartAt), 64, two_pass);
    EXPECT_GT(r.part_pixels, 2000);
    EXPECT_EQ(r.visible_pixels, 0);
    EXPECT_EQ(r.V, 0.0);
  }
}

TEST(Visibility, EyeInsideTheBoundingSphereSeesNothing) {
  const auto r = Cast(BallMesh(), {Plate(-0.5, 0.0)}, At(kPartAt), 64, false, kPartAt);
  EXPECT_EQ(r.path, VisibilityPath::kEyeInsideBoundingSphere);
  EXPECT_EQ(r.V, 0.0);
  EXPECT_EQ(r.rays_cast, 0);
}

// One row of the discretization table: V at each N against the exact value.
struct Case {
  const char* name;
  double exact;
  double bound_times_n;  // asserted |V - exact| <= bound_times_n / N
  std::function<VisibilityResult(int)> cast;
};

void ExpectConverges(const Case& c) {
  std::printf("%s: exact V = %.6f\n%6s %10s %10s %10s %10s\n", c.name, c.exact, "N",
              "V_b", "V", "error", "bound");
  for (const int n : {32, 64, 128, 256, 512}) {
    const VisibilityResult r = c.cast(n);
    const double error = r.V - c.exact;
    std::printf("%6d %10lld %10.6f %10.2e %10.2e\n", n,
                static_cast<long long>(r.part_pixels), r.V, error, c.bound_times_n / n);
    EXPECT_LE(std::abs(error), c.bound_times_n / n) << c.name << " at N = " << n;
  }
}

TEST(Visibility, BallHalfHiddenConverges) {
  const auto ball = BallMesh();
  const double turn = 0.3;  // the edge is not along a pixel row
  ExpectConverges({"ball, plate edge through the line of sight", 0.5, 0.1, [&](int n) {
                     return Cast(ball, {Plate(0.0, turn)}, At(kPartAt), n);
                   }});
  const double h = 0.3;  // edge offset, as a fraction of the disc radius
  const double hidden = (std::acos(h) - h * std::sqrt(1 - h * h)) / M_PI;
  const double x_edge = h * kDisc * (kPlateY + kPlateHalfThickness);
  ASSERT_NEAR(ImageOfEdge(x_edge), h * kDisc, 1e-15);
  ExpectConverges(
      {"ball, plate edge 0.3 t off the line of sight", 1 - hidden, 0.1,
       [&](int n) { return Cast(ball, {Plate(x_edge, turn)}, At(kPartAt), n); }});
}

TEST(Visibility, BoxFaceOnBehindPlateConverges) {
  const double w = 0.08, depth = 0.04, turn = 0.37;
  const auto box = Tessellate(Box{{w, depth, w}}, 1e-4);
  const double half = (w / 2) / (kPartAt.y() - depth / 2);  // near face's image
  const double x_edge = 0.4 * half * (kPlateY + kPlateHalfThickness);
  const double covered = (half - ImageOfEdge(x_edge)) / (2 * half);  // 0.3
  ExpectConverges({"box face-on, plate covering 0.3 of it", 1 - covered, 0.1, [&](int n) {
                     return Cast(box, {Plate(x_edge, turn)}, At(kPartAt) * AboutY(turn),
                                 n);
                   }});
}

TEST(Visibility, RotatingSceneAndEyeTogetherKeepsV) {
  const double w = 0.08, depth = 0.04, turn = 0.37;
  const auto box = Tessellate(Box{{w, depth, w}}, 1e-4);
  const Occluder plate = Plate(0.4 * (w / 2) / 0.98 * 0.501, turn);
  const Isometry3d X_WP = At(kPartAt) * AboutY(turn);
  // About an arbitrary axis through an arbitrary point.
  Isometry3d Q = At({0.3, -0.2, 0.1});
  Q.rotate(Eigen::AngleAxisd(1.234, Vector3d(0.3, -0.5, 0.8).normalized()));
  Q.translate(Vector3d(-0.3, 0.2, -0.1));
  for (const int n : {64, 256}) {
    const double v = Cast(box, {plate}, X_WP, n).V;
    const double turned =
        Cast(box, {{plate.mesh, Q * plate.X_WO}}, Q * X_WP, n, false, Q * kEye).V;
    std::printf("N = %d: V = %.6f, rotated %.6f\n", n, v, turned);
    EXPECT_NEAR(turned, v, 0.2 / n) << "N = " << n;
  }
}

TEST(Visibility, OneTraversalCountsEqualTwoPasses) {
  const auto ball = BallMesh();
  for (const double x_edge : {-0.5, -0.02, 0.0, 0.01}) {
    const auto one = Cast(ball, {Plate(x_edge, 0.3)}, At(kPartAt), 96, false);
    const auto two = Cast(ball, {Plate(x_edge, 0.3)}, At(kPartAt), 96, true);
    EXPECT_EQ(one.part_pixels, two.part_pixels) << x_edge;
    EXPECT_EQ(one.visible_pixels, two.visible_pixels) << x_edge;
    EXPECT_EQ(two.rays_cast, 2 * 96 * 96);
    // Once per pixel in the bounding cone, again only where an occluder came first.
    EXPECT_LT(one.rays_cast, two.rays_cast);
  }
}

TEST(Visibility, SameInputsSameBitsAndPoseFollowsTheInstance) {
  const auto ball = BallMesh();
  VisibilityCaster caster(ball, {Plate(0.0, 0.3)}, {128, false});
  const VisibilityResult first = caster.Compute(kEye, At(kPartAt));
  // Move the part clear of the plate and back: the instance follows.
  const VisibilityResult clear = caster.Compute(kEye, At({-0.4, 1.0, 0.0}));
  const VisibilityResult again = caster.Compute(kEye, At(kPartAt));
  const VisibilityResult fresh = Cast(ball, {Plate(0.0, 0.3)}, At(kPartAt), 128);
  EXPECT_EQ(clear.V, 1.0);
  for (const auto& r : {again, fresh}) {
    EXPECT_EQ(r.part_pixels, first.part_pixels);
    EXPECT_EQ(r.visible_pixels, first.visible_pixels);
    EXPECT_EQ(r.rays_cast, first.rays_cast);
    EXPECT_EQ(std::memcmp(&r.V, &first.V, sizeof(double)), 0);
  }
}

// The peg scene from the operator's eye: the deeper the peg sits in the bore,
// the less of it shows; lifted clear of the bore it is wholly seen, and lifted
// well clear nothing can hide it.
TEST(Visibility, PegSinksOutOfSightIntoTheBore) {
  const scene::Scene peg_scene = scene::LoadScene(std::string(VAHF_SOURCE_DIR) +
                                                  "/experiments/scenes/peg_in_hole.json");
  const scene::Part& peg = peg_scene.parts[peg_scene.sequence.front()];
  std::vector<Occluder> fixed;
  for (const scene::Part& p : peg_scene.parts)
    if (p.role != scene::Role::kAssembling)
      fixed.push_back({Tessellate(p.shape, 1e-4), p.initial.Transform()});
  VisibilityCaster caster(Tessellate(peg.shape, 1e-4), fixed, {128, false});
  const Vector3d eye = human::StandingPosture(peg_scene.op).eye;
  double last = 1.0;
  for (const double raised : {0.2, 0.05, 0.03, 0.02, 0.01, 0.0}) {
    Isometry3d X_WP = peg.target.Transform();
    X_WP.translation().z() += raised;
    const VisibilityResult r = caster.Compute(eye, X_WP);
    std::printf("peg %.0f mm above its target: V = %.4f (%s, %lld rays)\n", 1e3 * raised,
                r.V, VisibilityPathName(r.path), static_cast<long long>(r.rays_cast));
    if (raised >= 0.2) {
      EXPECT_EQ(r.path, VisibilityPath::kNothingCanHide);
    } else if (raised >= 0.05) {  // above the bore's top (the bore is behind it)
      EXPECT_EQ(r.path, VisibilityPath::kRaysCast);
      EXPECT_EQ(r.V, 1.0);
    } else {
      EXPECT_LT(r.V, last) << raised;
    }
    last = r.V;
  }
  EXPECT_GT(last, 0.0);  // at the target its top still stands 10 mm proud
}

TEST(Visibility, RejectsBadInput) {
  const auto ball = BallMesh();
  for (const int grid : {0, -3, kMaxGrid + 1}) {
    try {
      VisibilityCaster caster(ball, {}, {grid, false});
      ADD_FAILURE() << "accepted grid " << grid;
    } catch (const InputError& e) {
      EXPECT_THAT(e.what(), ::testing::HasSubstr("must be an integer from 1 to 1024"));
    }
  }
  EXPECT_THROW(VisibilityCaster(geometry::TriangleMesh{}, {}), InputError);
  // N = 1: one ray, to the ball's centre, passing 1 cm beside the plate's edge.
  VisibilityCaster single(ball, {Plate(0.01, 0.0)}, {1, false});
  EXPECT_EQ(single.Compute(kEye, At(kPartAt)).V, 1.0);
  VisibilityCaster caster(ball, {Plate(0.0, 0.0)});
  try {
    caster.Compute(Vector3d(0, NAN, 0), At(kPartAt));
    ADD_FAILURE() << "accepted a NaN eye";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(),
                ::testing::HasSubstr("eye position = [0, nan, 0]: must be finite"));
  }
  EXPECT_THROW(caster.Compute(kEye, At({0, INFINITY, 0})), InputError);
}

}  // namespace
}  // namespace vahf::visibility
