#include "vahf/kinds/lab_run.h"

namespace vahf::kinds {

report::RunOutput WriteLabRun(const scene::ExperimentFile& file,
                              const data::LabDataset& lab, const RunContext& context,
                              int trials, const std::string& cycles,
                              const report::Section& section,
                              const report::RunInfo& info) {
  report::RunHeader h;
  h.file = &file;
  h.first = &file;
  h.seed = context.settings.seed;
  h.trials = trials;
  h.cycles_per_condition = std::to_string(trials) + cycles;
  h.integration = report::IntegrationText(file.scene.params);
  h.inputs = {file.scene_path};
  for (const std::string& f : data::LabDatasetFiles(lab)) h.inputs.push_back(f);
  if (!file.overrides_path.empty()) h.inputs.push_back(file.overrides_path);
  return report::WriteSections(h, {section}, *context.directory, info);
}

}  // namespace vahf::kinds
