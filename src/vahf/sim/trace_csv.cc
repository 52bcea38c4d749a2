#include "vahf/sim/trace_csv.h"

#include <fmt/format.h>

#include <algorithm>

namespace vahf::sim {

std::string TraceCsv(const TrialResult& result) {
  std::string out =
      "row,t,x,y,z,qw,qx,qy,qz,vx,vy,vz,wx,wy,wz,assembly_fx,assembly_fy,assembly_fz,"
      "contact_fx,contact_fy,contact_fz,friction_fx,friction_fy,friction_fz,"
      "V,f,eta,r,g,lambda_c,A,psi,penetration\n";
  const auto v3 = [](const Eigen::Vector3d& v) {
    return fmt::format("{:.17g},{:.17g},{:.17g}", v.x(), v.y(), v.z());
  };
  const auto row = [&](const char* kind, const TraceRow& r) {
    const auto& f = r.factors;
    out += fmt::format(
        "{},{:.17g},{},{:.17g},{:.17g},{:.17g},{:.17g},{},{},{},{},{},"
        "{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g},{:.17g}\n",
        kind, r.time, v3(r.position), r.orientation.w(), r.orientation.x(),
        r.orientation.y(), r.orientation.z(), v3(r.velocity), v3(r.angular_velocity),
        v3(r.assembly_force), v3(r.contact_force), v3(r.friction_force), f.V, f.f, f.eta,
        f.r, f.g, f.lambda_c, r.work, r.psi, r.penetration);
  };
  // Decision and sample rows merged in time order (a decision first at a tie).
  std::size_t i = 0, j = 0;
  const auto& d = result.trace;
  const auto& s = result.samples;
  while (i < d.size() || j < s.size()) {
    if (j == s.size() || (i < d.size() && d[i].time <= s[j].time))
      row("decision", d[i++]);
    else
      row("sample", s[j++]);
  }
  return out;
}

}  // namespace vahf::sim
