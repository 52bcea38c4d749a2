// The precision experiment as a design over cycles (docs/experiments.md,
// "precision"): for each scene, the reference and each setting is a
// condition; condition k of a scene runs that scene with the setting's
// parameter overrides. Cycle j of every condition uses the same streams
// (common random numbers, RunDesign), so a setting and the reference differ
// by the setting only and are compared cycle by cycle.
#pragma once

#include <cstddef>
#include <vector>

#include "vahf/experiment/design.h"
#include "vahf/experiment/precision_input.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::experiment {

// Scene-major: for each scene of file.precision, the reference, then the
// settings in file order. A condition's name is the setting's label, its
// group the scene's name, its trials the scene's cycles per setting:
// trials_override if > 0, else the scene's own, else the file's.
std::vector<Condition> PrecisionConditions(const scene::ExperimentFile& file,
                                           int trials_override);

// The index in PrecisionConditions of scene `scene`'s setting `setting`:
// 0 is the reference, k + 1 the file's setting k.
std::size_t PrecisionConditionIndex(const PrecisionDesign& design, std::size_t scene,
                                    std::size_t setting);

}  // namespace vahf::experiment
