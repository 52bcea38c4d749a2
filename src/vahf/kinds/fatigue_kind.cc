// The fatigue kind (docs/experiments.md, "fatigue"): an hour of work in
// segments.
#include "vahf/experiment/design.h"
#include "vahf/experiment/fatigue_input.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/section.h"

namespace vahf::kinds {

Kind FatigueKind() {
  Kind k;
  k.name = "fatigue";
  k.summary = "success rate and time over an hour of work (Sec. 5.4)";
  k.doc = "experiments.md#fatigue-sec-54-figs-15-16";
  k.keys = {"fatigue"};
  k.parse = experiment::ReadFatigueExperiment;
  k.check = CheckOneScene;
  k.design = experiment::FatigueExperimentRun;
  k.conditions = experiment::FatigueConditions;
  k.analyse = report::FatigueSection;
  return k;
}

}  // namespace vahf::kinds
