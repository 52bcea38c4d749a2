#include "vahf/experiment/groups_input.h"

#include <fmt/format.h>

#include <memory>
#include <utility>

#include "vahf/scene/overrides.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::experiment {

void GroupsInput::ApplyOverrides(const scene::ParameterOverrides& o,
                                 scene::ExperimentFile*) {
  for (ConditionEntry& c : conditions) scene::ApplyOverrides(o, &c.scene);
}

std::vector<std::string> GroupsInput::InputFiles() const {
  std::vector<std::string> out;
  for (const ConditionEntry& c : conditions) out.push_back(c.scene_path);
  return out;
}

void ReadHumanFactorsGroups(const scene::JsonNode& root, const std::string& path,
                            scene::ExperimentFile* file) {
  auto in = std::make_unique<GroupsInput>();
  const scene::JsonNode list = root.Required("conditions");
  const std::size_t n = list.ArraySize(1);
  for (std::size_t k = 0; k < n; ++k) {
    const scene::JsonNode c = list.At(k);
    c.ExpectObject({"name", "scene"});
    ConditionEntry entry;
    entry.name = c.Required("name").String();
    entry.scene_path = scene::ResolvePath(c.Required("scene"), path, "scene");
    entry.scene = scene::LoadScene(entry.scene_path);
    for (const ConditionEntry& other : in->conditions)
      if (other.name == entry.name)
        c.Required("name").Fail("condition names must be unique");
    in->conditions.push_back(std::move(entry));
  }
  if (auto cycle = root.Optional("paper_cycle_s")) in->paper_cycle_s = cycle->Positive();
  const scene::JsonNode instants = root.Required("instants_s");
  const std::size_t m = instants.ArraySize(1);
  for (std::size_t k = 0; k < m; ++k) {
    const double t = instants.At(k).Positive();
    if (t > in->paper_cycle_s)
      instants.At(k).Fail(
          fmt::format("an instant lies within the paper's cycle, paper_cycle_s = {} s",
                      in->paper_cycle_s));
    in->instants_s.push_back(t);
  }
  file->input = core::ClonePtr<scene::KindInput>(std::move(in));
}

}  // namespace vahf::experiment
