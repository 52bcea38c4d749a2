// The assembly_time kind (docs/experiments.md, "assembly_time"): assembly time
// per operator.
#include "vahf/experiment/assembly_time_input.h"
#include "vahf/experiment/design.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/section.h"

namespace vahf::kinds {

Kind AssemblyTimeKind() {
  Kind k;
  k.name = "assembly_time";
  k.summary = "assembly time per operator (Sec. 5.2)";
  k.doc = "experiments.md#assembly_time-sec-52-figs-11-12";
  k.keys = {"operators"};
  k.parse = experiment::ReadAssemblyTime;
  k.check = CheckOneScene;
  k.design = experiment::AssemblyTimeRun;
  k.conditions = experiment::AssemblyTimeConditions;
  k.analyse = report::AssemblyTimeSection;
  k.times_the_parts = true;
  return k;
}

}  // namespace vahf::kinds
