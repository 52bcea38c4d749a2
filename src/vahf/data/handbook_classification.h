// Which handbook class a part's insertion falls in, as the scene describes the
// fit: the MTM-1 Position class (fit class and symmetry) and the
// Boothroyd-Dewhurst manual insertion code, each with a one-line reason and,
// where the shipped table has the row, its time in seconds. The rules and
// their sources: docs/handbooks.md.
#pragma once

#include <optional>
#include <string>

#include "vahf/data/handbook.h"
#include "vahf/scene/scene.h"

namespace vahf::data {

// A clearance fit is "close" below this diametral clearance per unit
// diameter, (D_hole - d_part) / d, and "loose" at or above it. vahf's choice,
// not a handbook value: neither handbook as found gives a number (see
// data/handbooks/README.md). 2/1000 puts ISO 286 H8/f7 pairs ("close running"
// in the ANSI B4.2 preferred-fit names) of the shipped cylinder (1.1/1000 at
// 63 mm, 1.6/1000 at 36 mm) among the close fits, and the peg's 5/1000 among
// the loose.
inline constexpr double kCloseFitClearanceRatio = 2e-3;

// The insertion as the scene gives it. Lengths in m.
struct InsertionFit {
  double radial_clearance = 0;         // hole radius - part radius; < 0: interference
  double diameter = 0;                 // of the fit, > 0
  bool chamfered = false;              // a lead-in chamfer on either part
  bool rotationally_symmetric = true;  // about the insertion axis
  bool lubricated = false;
  bool pressure_required = false;  // an interference or press fit
  // What the scene does not say; the defaults are the shipped scenes' case
  // (a bench-top part, in view, that stays where it is put).
  bool easy_to_handle = true;
  bool obstructed_access = false;
  bool restricted_vision = false;
  bool holding_down_required = false;
};

struct MtmClass {
  int fit_class = 0;     // 1 loose, 2 close, 3 exact
  std::string symmetry;  // "S" or "NS" (the scene cannot say "SS")
  std::string code;      // e.g. "P2SE"
  std::string why;
  std::optional<double> seconds;  // the table's TMU x 0.036 s, if it has the row
};

struct BdClass {
  std::string code;  // two digits
  std::string why;
  std::optional<double> seconds;  // the table's, if it has the row
};

struct HandbookClasses {
  MtmClass mtm;
  BdClass bd;
};

// Classifies `fit`; the times come from `mtm` and `bd`. Throws InputError
// (empty file, where "diameter" or "radial_clearance") for a diameter that is
// not positive and finite or a clearance that is not finite.
HandbookClasses ClassifyInsertion(const InsertionFit& fit, const MtmPositionTable& mtm,
                                  const BdInsertionTable& bd);

// The fit of the part at `position` of the scene's sequence, as the scene
// gives it: the smallest radial clearance between the part at its target and
// a part fixed during its trial (geometry::SmallestRadialFit), that fit's bore
// diameter; chamfered when the part's or that fixed part's profile has an
// edge changing both radius and height (a conical lead-in); symmetric when the
// part is revolved; lubricated when contact/lubricant_viscosity > 0; never a
// press fit (a clearance was found). Nothing, with `why` saying so, when the
// part has no radial fit (a box, or no coaxial facing faces).
std::optional<InsertionFit> InsertionFitOf(const scene::Scene& scene,
                                           std::size_t position, std::string* why);

}  // namespace vahf::data
