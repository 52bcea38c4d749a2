#include "vahf/sim/trace_csv.h"

#include <fmt/format.h>


namespace vahf::sim {

std::string TraceCsv(const TrialResult& result) {
  std::string out =
      "t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,assembly_fx,assembly_fy,assembly_fz,"
      "contact_fx,contact_fy,contact_fz,friction_fx,friction_fy,friction_fz,"
      "V,f,eta,r,g,lambda_c,A,psi\n";
  const auto v3 = [](const Eigen::Vector3d& v) {
    return fmt::format("{:.17g},{:.17g},{:.17g}", v.x(), v.y(), v.z());
  };
  for (const TraceRow& r : result.trace) {
    const auto& f = r.factors;
    out += fmt::format(
        "{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{},{},{},{},{},"
        "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n",
        r.time, v3(r.position), r.orientation.w(), r.orientation.x(), r.orientation.y(),
        r.orientation.z(), v3(r.velocity), v3(r.angular_velocity), v3(r.assembly_force),
        v3(r.contact_force), v3(r.friction_force), f.V, f.f, f.eta, f.r, f.g, f.lambda_c,
        r.work, r.psi);
  }
  return out;
}

}  // namespace vahf::sim
