#include "vahf/experiment/precision_design.h"

#include <memory>

namespace vahf::experiment {

std::vector<Condition> PrecisionConditions(const scene::ExperimentFile& file,
                                           int trials_override) {
  const PrecisionDesign& d = file.Input<PrecisionDesign>();
  std::vector<Condition> out;
  for (const PrecisionScene& s : d.scenes) {
    const int trials = trials_override > 0 ? trials_override
                       : s.trials > 0      ? s.trials
                                           : file.trials;
    const auto add = [&](const PrecisionSetting& setting, const scene::Scene& scene) {
      Condition c;
      c.name = setting.label;
      c.group = s.scene.name;
      c.scene = std::make_shared<const scene::Scene>(scene);
      c.trials = trials;
      out.push_back(std::move(c));
    };
    add(d.reference, s.reference);
    for (std::size_t k = 0; k < d.settings.size(); ++k) add(d.settings[k], s.settings[k]);
  }
  return out;
}

std::size_t PrecisionConditionIndex(const PrecisionDesign& design, std::size_t scene,
                                    std::size_t setting) {
  return scene * (design.settings.size() + 1) + setting;
}

}  // namespace vahf::experiment
