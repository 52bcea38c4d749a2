#include "vahf/kinds/check_file.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "vahf/calibrate/synthetic_lab.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/run_support.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/overrides.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::kinds {

std::string CheckFile(const std::string& path) {
  const nlohmann::json document = scene::ReadJsonFile(path);  // read once
  const std::string format = scene::FormatOf(document, path);
  std::string out;
  if (format == "lab") {
    out = data::DescribeLabDataset(data::ParseLabDataset(document, path));
  } else if (format == "overrides") {
    const scene::ParameterOverrides o = scene::LoadOverrides(path);
    out = fmt::format("parameter overrides ({}){}{}\n", path,
                      o.source.empty() ? "" : ": ", o.source);
    for (const auto& [name, value] : o.values)
      out += fmt::format("  {} = {}\n", name, value.dump());
  } else if (format == "synthetic") {
    const calibrate::SyntheticLabSpec spec = calibrate::LoadSyntheticLabSpec(path);
    out = fmt::format(
        "synthetic lab '{}': scene {}, {} operator(s) x {} repetitions, seed {}, "
        "reading error sd {:g} s, resolution {:g} s\n",
        spec.name, spec.scene_path, spec.operators.size(), spec.repetitions, spec.seed,
        spec.time_sd, spec.time_resolution);
    for (const auto& [name, value] : spec.truth)
      out += fmt::format("  {} = {:g} (stated)\n", name, value);
    out += DescribeSceneModels(spec.scene);
  } else if (format == "scene") {
    out = DescribeSceneModels(scene::ParseScene(document, path));
  } else {
    out = CheckExperiment(ParseExperiment(document, path));
  }
  return out + fmt::format("{}: valid {}\n", path,
                           format == "lab"         ? "lab dataset"
                           : format == "overrides" ? "parameter override file"
                           : format == "synthetic" ? "synthetic lab generator"
                                                   : format.c_str());
}

}  // namespace vahf::kinds
