// The human_factors_groups kind (docs/experiments.md, "human_factors_groups"):
// human factors per working condition, each condition its own scene.
#include <fmt/format.h>

#include <string>

#include "vahf/experiment/design.h"
#include "vahf/experiment/groups_input.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/section.h"

namespace vahf::kinds {
namespace {

std::string CheckGroups(const scene::ExperimentFile& file) {
  std::string out;
  for (const experiment::ConditionEntry& c :
       file.Input<experiment::GroupsInput>().conditions)
    out += fmt::format("condition '{}' ({}):\n", c.name, c.scene_path) +
           DescribeSceneModels(c.scene);
  return out;
}

}  // namespace

Kind HumanFactorsGroupsKind() {
  Kind k;
  k.name = "human_factors_groups";
  k.summary = "human factors per working condition (Sec. 5.3)";
  k.doc = "experiments.md#human_factors_groups-sec-53-figs-13-14";
  k.keys = {"conditions", "instants_s", "paper_cycle_s"};
  k.parse = experiment::ReadHumanFactorsGroups;
  k.check = CheckGroups;
  k.design = experiment::HumanFactorsGroupsRun;
  k.conditions = experiment::HumanFactorsGroupsConditions;
  k.analyse = report::HumanFactorsGroupsSection;
  return k;
}

}  // namespace vahf::kinds
