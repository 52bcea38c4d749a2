#include "vahf/kinds/synthesize.h"

#include <fmt/format.h>

#include "vahf/calibrate/synthetic_lab.h"
#include "vahf/data/lab_dataset.h"

namespace vahf::kinds {

std::string Synthesize(const std::string& generator, const std::string& out,
                       experiment::RunnerOptions options) {
  const calibrate::SyntheticLabSpec spec = calibrate::LoadSyntheticLabSpec(generator);
  options.label = spec.name + " (synthetic lab)";
  options.unit = "cycles";
  const data::LabDataset lab = calibrate::GenerateSyntheticLab(spec, options);
  data::WriteLabDataset(lab, out);
  std::string segments;
  if (!lab.segments.empty())
    segments = fmt::format(" and {} segment row(s)", lab.segments.size());
  return fmt::format("{}: {} trials of {} operator(s){} written to {}/dataset.json\n",
                     spec.name, lab.trials.size(), spec.operators.size(), segments, out);
}

}  // namespace vahf::kinds
