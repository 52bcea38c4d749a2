#include "vahf/data/handbook_classification.h"

#include <fmt/format.h>

#include <cmath>
#include <variant>

#include "vahf/core/error.h"
#include "vahf/geometry/clearance.h"

namespace vahf::data {
namespace {

// MTM-1 class of fit (the data card's Position table: 1 loose, no pressure
// required; 2 close, light pressure required; 3 exact, heavy pressure
// required). A press or interference fit is class 3; a clearance fit is class
// 2 below kCloseFitClearanceRatio and class 1 at or above it. Oil does not
// change the class: MTM classes the fit, not the friction.
MtmClass MtmOf(const InsertionFit& fit, double ratio, const MtmPositionTable& table) {
  MtmClass c;
  if (fit.pressure_required) {
    c.fit_class = 3;
    c.why = "class 3 (exact): the fit needs pressure (interference or press fit)";
  } else if (ratio < kCloseFitClearanceRatio) {
    c.fit_class = 2;
    c.why = fmt::format(
        "class 2 (close): diametral clearance {:.2g} of the diameter, below {:.2g}",
        ratio, kCloseFitClearanceRatio);
  } else {
    c.fit_class = 1;
    c.why = fmt::format(
        "class 1 (loose): diametral clearance {:.2g} of the diameter, at least {:.2g}",
        ratio, kCloseFitClearanceRatio);
  }
  // A solid of revolution goes in at any angle about its axis: symmetric.
  c.symmetry = fit.rotationally_symmetric ? "S" : "NS";
  c.why += fit.rotationally_symmetric
               ? "; symmetric (revolved about the insertion axis)"
               : "; taken as non-symmetric (not revolved; the scene cannot tell SS)";
  const std::string handling = fit.easy_to_handle ? "easy" : "difficult";
  c.code = MtmPositionCode(c.fit_class, c.symmetry, handling);
  c.why += "; " + handling + " to handle";
  if (const MtmPositionTime* row = table.Find(c.code)) c.seconds = row->seconds();
  return c;
}

// Boothroyd-Dewhurst manual insertion chart. Rows: a part that stays where it
// is put without being secured (0-2), or one secured at once by its push fit
// (3-5); access and vision add 1 (obstructed or restricted) or 2 (both).
// Columns of rows 0-2: +6 with holding down; +2 not easy to align and
// position (no chamfer to lead it in); +1 resistance to insertion. Rows 3-5:
// 0 easy and no resistance, 1 otherwise.
BdClass BdOf(const InsertionFit& fit, double ratio, const BdInsertionTable& table) {
  BdClass c;
  const int access = (fit.obstructed_access ? 1 : 0) + (fit.restricted_vision ? 1 : 0);
  const bool align_easy = fit.chamfered;
  // Resistance: a press fit, or a close fit without oil, which drags (the
  // chart's resistance to insertion; the threshold is kCloseFitClearanceRatio).
  const bool resistance =
      fit.pressure_required || (ratio < kCloseFitClearanceRatio && !fit.lubricated);
  int row = access, column = 0;
  if (fit.pressure_required) {
    row += 3;
    column = align_easy && !resistance ? 0 : 1;
    c.why = "secured immediately by its press fit";
  } else {
    column =
        (fit.holding_down_required ? 6 : 0) + (align_easy ? 0 : 2) + (resistance ? 1 : 0);
    c.why = fit.holding_down_required ? "added, not secured, held down"
                                      : "added, not secured, stays put";
  }
  c.why += access == 0   ? "; easy reach and view"
           : access == 1 ? "; obstructed access or restricted vision"
                         : "; obstructed access and restricted vision";
  c.why += align_easy ? "; easy to align (chamfered lead-in)"
                      : "; not easy to align (no chamfer)";
  c.why += resistance ? (fit.pressure_required ? "; resistance (pressure needed)"
                                               : "; resistance (dry close fit)")
                      : "; no resistance";
  c.code = fmt::format("{}{}", row, column);
  if (const BdInsertionTime* r = table.Find(c.code)) c.seconds = r->seconds;
  return c;
}

// Whether a shape's profile has a conical edge (both r and z change): a
// chamfer or another lead-in.
bool HasConicalEdge(const geometry::Shape& shape) {
  const auto* p = std::get_if<geometry::RevolvedProfile>(&shape);
  if (!p) return false;
  const auto& v = p->vertices;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const geometry::ProfilePoint a = v[k], b = v[(k + 1) % v.size()];
    if (a.r != b.r && a.z != b.z) return true;
  }
  return false;
}

}  // namespace

std::optional<InsertionFit> InsertionFitOf(const scene::Scene& scene,
                                           std::size_t position, std::string* why) {
  const scene::Part& part =
      scene.parts.at(static_cast<std::size_t>(scene.sequence.at(position)));
  const std::optional<scene::TightFit> tight =
      scene::TightestFit(part, scene::FixedPartsAt(scene, position));
  if (!tight) {
    *why = fmt::format(
        "{} has no radial fit with a fixed part at its target (no coaxial cylindrical "
        "faces facing each other)",
        part.name);
    return std::nullopt;
  }
  InsertionFit fit;
  const geometry::RadialFit& best = tight->fit;
  const scene::Part* other = tight->with;
  fit.radial_clearance = best.clearance;
  fit.diameter = 2 * best.bore_radius;
  fit.chamfered = HasConicalEdge(part.shape) || HasConicalEdge(other->shape);
  fit.rotationally_symmetric =
      std::holds_alternative<geometry::RevolvedProfile>(part.shape);
  fit.lubricated = scene.params.contact.lubricant_viscosity > 0;
  *why = fmt::format("{} with the {}: {:.1f} um radial clearance at {:.1f} mm{}{}",
                     part.name, other->name, 1e6 * fit.radial_clearance,
                     1e3 * fit.diameter, fit.chamfered ? ", chamfered" : ", no chamfer",
                     fit.lubricated ? ", oiled" : ", dry");
  return fit;
}

HandbookClasses ClassifyInsertion(const InsertionFit& fit, const MtmPositionTable& mtm,
                                  const BdInsertionTable& bd) {
  if (!(std::isfinite(fit.diameter) && fit.diameter > 0))
    throw InputError("", "diameter", fmt::format("{}", fit.diameter),
                     "a fit's diameter is positive and finite, m");
  if (!std::isfinite(fit.radial_clearance))
    throw InputError("", "radial_clearance", fmt::format("{}", fit.radial_clearance),
                     "a fit's radial clearance is finite, m");
  const double ratio = 2 * fit.radial_clearance / fit.diameter;
  return {MtmOf(fit, ratio, mtm), BdOf(fit, ratio, bd)};
}

}  // namespace vahf::data
