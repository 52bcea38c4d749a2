// The operator's decisions (paper Sec. 3.1, Fig. 2; docs/design.md decisions 1
// and 10), without Simbody: at every t_i = i * decision_interval the human
// factors, fatigue, the outcome checks, the Eq. 5 draws and the trace row;
// and the row at the instant a trial ends. Any stepper calls them with the
// part's motion at that instant.
#pragma once

#include <optional>

#include "vahf/contact/contact_model.h"
#include "vahf/sim/internal/trial_context.h"
#include "vahf/sim/trial_model.h"

namespace vahf::sim::internal {

// The decision at `time` (a decision instant) for the part at motion m, to be
// held until the next; nothing when this instant was decided already. May end
// the trial (c.ended): the decision then holds the part's own pose.
std::optional<Decision> Decide(TrialContext& c, double time,
                               const contact::RigidMotion& m);

// The row at the instant the trial ended: where the part is, its factors (f
// from the travel since the last decision), and A with that last stretch of
// travel added under the force held since the decision (Eq. 4).
TraceRow FinalRow(TrialContext& c, double time, const contact::RigidMotion& m);

}  // namespace vahf::sim::internal
