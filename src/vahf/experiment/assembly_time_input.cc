#include "vahf/experiment/assembly_time_input.h"

#include <memory>

#include "vahf/core/error.h"
#include "vahf/scene/overrides.h"

namespace vahf::experiment {

void AssemblyTimeInput::ApplyOverrides(const scene::ParameterOverrides& o,
                                       scene::ExperimentFile* file) {
  for (const scene::OperatorEntry& op : operators) {
    const std::string violation =
        file->scene.params.reach.Violation(op.arm_length, op.height);
    if (!violation.empty())
      throw InputError(o.file, "/parameters",
                       "applied to scene '" + file->scene.name + "' with operator '" +
                           op.name + "' of " + file->file,
                       violation);
  }
}

void ReadAssemblyTime(const scene::JsonNode& root, const std::string&,
                      scene::ExperimentFile* e) {
  auto input = std::make_unique<AssemblyTimeInput>();
  if (auto ops = root.Optional("operators"))
    input->operators = scene::ReadOperators(*ops, e->scene);
  e->input = core::ClonePtr<scene::KindInput>(std::move(input));
}

}  // namespace vahf::experiment
