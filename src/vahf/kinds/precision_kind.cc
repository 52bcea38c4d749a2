// The precision kind (docs/experiments.md, "precision"): error against run
// time of integrators and model settings.
#include <string>

#include "vahf/experiment/design.h"
#include "vahf/experiment/precision_design.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/report/section.h"
#include "vahf/sim/trial_model.h"

namespace vahf::kinds {
namespace {

// The settings, and the trial models of every scene under every setting (what
// only building can reject, a setting's shell spacing say, fails now).
std::string CheckPrecision(const scene::ExperimentFile& file) {
  std::string out = experiment::DescribePrecision(file);
  for (const experiment::PrecisionScene& s :
       file.Input<experiment::PrecisionDesign>().scenes) {
    out += DescribeSceneModels(s.reference);
    for (const scene::Scene& setting : s.settings) sim::BuildSequenceModels(setting);
  }
  return out;
}

}  // namespace

Kind PrecisionKind() {
  Kind k;
  k.name = "precision";
  k.summary = "error against run time of integrators and model settings";
  k.doc = "experiments.md#precision-error-against-run-time";
  k.keys = {"scenes", "reference", "settings", "noise_trials"};
  k.scene_elsewhere = "a precision experiment names its scenes in \"scenes\"";
  k.parse = experiment::ReadPrecision;
  k.check = CheckPrecision;
  k.design = experiment::PrecisionRun;
  k.analyse = report::PrecisionSection;
  return k;
}

}  // namespace vahf::kinds
