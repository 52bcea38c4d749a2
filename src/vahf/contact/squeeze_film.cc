#include "vahf/contact/squeeze_film.h"

#include <algorithm>
#include <cmath>
#include <unsupported/Eigen/AutoDiff>

#include "vahf/geometry/clearance.h"

namespace vahf::contact {
namespace {

// Gauss-Legendre on [-1, 1], 6 points (Abramowitz and Stegun, Handbook of
// Mathematical Functions, 1964, Table 25.4): exact for polynomials of degree
// 11; the integrand is smooth along a face except where eps nears the cap.
constexpr int kNodes = 6;
constexpr double kNode[kNodes] = {-0.932469514203152, -0.661209386466265,
                                  -0.238619186083197, 0.238619186083197,
                                  0.661209386466265,  0.932469514203152};
constexpr double kWeight[kNodes] = {0.171324492379170, 0.360761573048139,
                                    0.467913934850262, 0.467913934850262,
                                    0.360761573048139, 0.171324492379170};

template <typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Mat3 = Eigen::Matrix<T, 3, 3>;

template <typename T>
struct FilmLoad {
  Vec3<T> force = Vec3<T>::Zero();   // world
  Vec3<T> torque = Vec3<T>::Zero();  // about the moving origin, world
};

using Ad = Eigen::AutoDiffScalar<Eigen::Matrix<double, 12, 1>>;

double Value(double x) { return x; }
double Value(const Ad& x) { return x.value(); }

// The cap's shrink q_cap / q = 1 / (1 + (q / q_max)^16)^(1/16): 1 at q = 0
// (q^16 underflows), so q_cap = q s never divides by q.
template <typename T>
T CapShrink(const T& q, double q_max) {
  using std::pow;
  return 1.0 / T(pow(T(1.0 + T(pow(T(q / q_max), 16.0))), 1.0 / 16.0));
}

double MaxEccentricitySquared(double floor_over_clearance) {
  return (1.0 - floor_over_clearance) * (1.0 - floor_over_clearance);
}

// The film of one face pair on the moving part at origin p, rotation R,
// velocity v and angular velocity w (world).
template <typename T>
void AddFace(const FilmFace& f, const FilmParams& params, const Vec3<T>& p,
             const Mat3<T>& R, const Vec3<T>& v, const Vec3<T>& w, FilmLoad<T>* out) {
  const Mat3<T> Ft = f.fixed_pose.linear().transpose().template cast<T>();
  const Vec3<T> origin = Ft * (p - f.fixed_pose.translation().template cast<T>());
  const Vec3<T> axis = Ft * R.col(2);  // the moving axis in the fixed frame
  // The fixed axial coordinate of the moving axis' point at z: origin.z +
  // axis.z z; the engaged stretch of the moving face is where it lies on the
  // fixed face.
  const T b = axis(2);
  if (!(std::abs(Value(b)) > 1e-6)) return;  // across the fixed axis: no film
  T lo = (f.fixed_lo - origin(2)) / b, hi = (f.fixed_hi - origin(2)) / b;
  if (hi < lo) std::swap(lo, hi);
  if (lo < T(f.moving_lo)) lo = T(f.moving_lo);
  if (hi > T(f.moving_hi)) hi = T(f.moving_hi);
  if (!(hi > lo)) return;
  const T length = hi - lo;
  const double c = f.clearance, r = f.radius;
  // C0 phi, the harmonic finite-length factor phi = L^2 / (L^2 + 12 R^2).
  const T scale = 12.0 * M_PI * params.viscosity * r * r * r / (c * c * c) *
                  (length * length / (length * length + 12.0 * r * r));
  const double q_max = MaxEccentricitySquared(params.film_floor / c);
  const Mat3<T> F = f.fixed_pose.linear().template cast<T>();
  const Vec3<T> vf = Ft * v, wf = Ft * w;  // fixed frame
  for (int k = 0; k < kNodes; ++k) {
    const T z = 0.5 * (lo + hi) + 0.5 * length * kNode[k];
    const Vec3<T> arm = axis * z;             // fixed frame, from the origin
    const Vec3<T> point = origin + arm;       // the moving axis at z
    const Vec3<T> rate = vf + wf.cross(arm);  // its velocity
    const Eigen::Matrix<T, 2, 1> e(point(0) / c, point(1) / c);  // eps vector
    const Eigen::Matrix<T, 2, 1> de(rate(0), rate(1));
    const T q = e.squaredNorm();
    const T s = CapShrink(q, q_max);
    const T qc = q * s;
    using std::sqrt;
    const T root = T(sqrt(T(1.0 - qc)));
    const T tangential = 2.0 / ((2.0 + qc) * root);
    // (radial - tangential) / qc = 3 / ((2 + q) (1 - q)^(3/2)): the radial
    // excess, which vanishes with eps, without dividing by it.
    const T excess = 3.0 / ((2.0 + qc) * (1.0 - qc) * root);
    const Eigen::Matrix<T, 2, 1> f2 =
        -(tangential * de + excess * s * e.dot(de) * e) * scale;
    const Vec3<T> load(f2(0), f2(1), T(0));
    const T weight = 0.5 * length * kWeight[k];
    const Vec3<T> load_world = F * load * weight;
    out->force += load_world;
    out->torque += (R.col(2) * z).cross(load_world);
  }
}

template <typename T>
FilmLoad<T> Film(const std::vector<FilmFace>& faces, const FilmParams& params,
                 const Vec3<T>& p, const Mat3<T>& R, const Vec3<T>& v, const Vec3<T>& w) {
  FilmLoad<T> out;
  for (const FilmFace& f : faces) AddFace(f, params, p, R, v, w, &out);
  return out;
}

}  // namespace

std::vector<FilmFace> FilmFaces(const geometry::RevolvedProfile& moving,
                                const geometry::RevolvedProfile& fixed,
                                const Eigen::Isometry3d& fixed_pose) {
  std::vector<FilmFace> out;
  for (const geometry::CylindricalFace& m : geometry::CylindricalFaces(moving))
    for (const geometry::CylindricalFace& x : geometry::CylindricalFaces(fixed)) {
      if (m.faces_out == x.faces_out) continue;
      const double gap = m.faces_out ? x.r - m.r : m.r - x.r;
      const double radius = 0.5 * (m.r + x.r);
      if (!(gap > 0) || gap > kThinFilm * radius) continue;
      out.push_back({radius, gap, m.z_lo, m.z_hi, x.z_lo, x.z_hi, fixed_pose});
    }
  return out;
}

double CappedEccentricitySquared(double q, double floor_over_clearance) {
  return q * CapShrink(q, MaxEccentricitySquared(floor_over_clearance));
}

SqueezeFilm::SqueezeFilm(std::vector<FilmFace> faces, FilmParams params)
    : faces_(std::move(faces)), params_(params) {}

ContactForces SqueezeFilm::DoEvaluate(const RigidMotion& m, ContactCounters& counters,
                                      ContactJacobian* jacobian) const {
  ++counters.evaluations;
  ContactForces out;
  if (!jacobian) {
    const FilmLoad<double> load =
        Film<double>(faces_, params_, m.pose.translation(), m.pose.linear(), m.velocity,
                     m.angular_velocity);
    out.film_force = load.force;
    out.torque = load.torque;
    return out;
  }
  // Forward-mode derivatives in the Jacobian's twelve directions (dx, dtheta,
  // v, w): R -> (I + [dtheta]x) R to first order.
  Vec3<Ad> p, v, w, dtheta;
  for (int i = 0; i < 3; ++i) {
    p(i) = Ad(m.pose.translation()(i), 12, i);
    dtheta(i) = Ad(0.0, 12, 3 + i);
    v(i) = Ad(m.velocity(i), 12, 6 + i);
    w(i) = Ad(m.angular_velocity(i), 12, 9 + i);
  }
  Mat3<Ad> turn;
  turn << Ad(1.0), -dtheta(2), dtheta(1), dtheta(2), Ad(1.0), -dtheta(0), -dtheta(1),
      dtheta(0), Ad(1.0);
  const Mat3<Ad> R = turn * m.pose.linear().cast<Ad>();
  const FilmLoad<Ad> load = Film<Ad>(faces_, params_, p, R, v, w);
  for (int i = 0; i < 3; ++i) {
    out.film_force(i) = load.force(i).value();
    out.torque(i) = load.torque(i).value();
    jacobian->film_force.row(i) = load.force(i).derivatives().transpose();
    jacobian->torque.row(i) = load.torque(i).derivatives().transpose();
  }
  return out;
}

}  // namespace vahf::contact
