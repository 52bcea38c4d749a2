#include "vahf/calibrate/calibration_input.h"

#include <fmt/format.h>

#include <memory>
#include <utility>

#include "vahf/core/error.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/scene/overrides.h"
#include "vahf/scene/parameter_table.h"

namespace vahf::calibrate {

using scene::CheckSegments;
using scene::ExperimentFile;
using scene::FindParam;
using scene::FitTarget;
using scene::JsonNode;
using scene::Parameters;
using scene::ParamName;
using scene::ParamNames;
using scene::ParamSpec;
using scene::ReadParamValue;
using scene::ReadTargets;
using scene::ResolvePath;
using scene::Scene;

namespace {

// A fitted parameter's bound must obey the parameter table's rule: the fit,
// its differences included, stays within the bounds
// (calibrate/feasible_difference.h).
void CheckBound(const ParamSpec& spec, const JsonNode& node, double value) {
  Parameters scratch;
  try {
    ReadParamValue(spec, JsonNode(nlohmann::json(value), node.file(), node.path()),
                   &scratch);
  } catch (const InputError& e) {
    node.Fail(fmt::format("the bound {} breaks {}'s rule: {}", value, ParamName(spec),
                          e.rule()));
  }
}

// A stage's parameters, targets and solver, from `node` (a stage of
// "stages", or the file's root for a file of one stage).
CalibrationStage ReadStage(const JsonNode& node, const CalibrationDesign& d,
                           const Scene& scene) {
  CalibrationStage stage;
  if (auto solver = node.Optional("solver"))
    stage.solver = solver->Choice({"levenberg_marquardt", "golden_section"});
  const JsonNode params = node.Required("parameters");
  const std::size_t n = params.ArraySize(1);
  if (stage.solver == "golden_section" && n != 1)
    params.Fail(
        "the golden_section solver fits exactly one parameter; use levenberg_marquardt, "
        "or one "
        "stage per parameter");
  for (std::size_t k = 0; k < n; ++k) {
    const JsonNode p_node = params.At(k);
    p_node.ExpectObject({"name", "start", "lower", "upper"});
    FitParameter p;
    p.pointer = p_node.path();
    const JsonNode name = p_node.Required("name");
    p.name = name.Choice(ParamNames());
    const ParamSpec& spec = *FindParam(p.name);
    if (!spec.real) name.Fail("a calibration fits real-valued parameters");
    for (const CalibrationStage& earlier : d.stages)
      for (const FitParameter& other : earlier.parameters)
        if (other.name == p.name)
          name.Fail("fitted once only (also at " + other.pointer + ")");
    for (const FitParameter& other : stage.parameters)
      if (other.name == p.name)
        name.Fail("fitted once only (also at " + other.pointer + ")");
    const JsonNode lower = p_node.Required("lower"), upper = p_node.Required("upper"),
                   start = p_node.Required("start");
    p.lower = lower.Number();
    p.upper = upper.Number();
    p.start = start.Number();
    if (!(p.lower < p.upper)) upper.Fail(fmt::format("must exceed lower = {}", p.lower));
    if (!(p.lower <= p.start && p.start <= p.upper))
      start.Fail(
          fmt::format("must lie within [lower, upper] = [{}, {}]", p.lower, p.upper));
    CheckBound(spec, lower, p.lower);
    CheckBound(spec, upper, p.upper);
    stage.parameters.push_back(p);
  }
  // Targets of segments and targets without one may share a stage: both
  // designs then run at each parameter vector (calibration.h).
  stage.targets = ReadTargets(node.Required("targets"), scene, false);
  return stage;
}

}  // namespace

std::vector<std::string> CalibrationDesign::InputFiles() const {
  return data::LabDatasetFiles(data::LoadLabDataset(lab_path));
}

void ReadCalibration(const JsonNode& root, const std::string& path, ExperimentFile* e) {
  CalibrationDesign d;
  d.fatigue = scene::ReadFatigue(root);
  d.lab_path = ResolvePath(root.Required("lab"), path, "lab dataset");
  if (auto step = root.Optional("relative_step"))
    d.relative_step = step->InRange(1e-4, 0.5);
  if (auto r = root.Optional("noise_replicates"))
    d.noise_replicates = static_cast<int>(r->Integer(0, 100));
  if (auto in = root.Optional("intervals")) d.intervals = in->Choice({"wald", "profile"});
  if (auto ls = root.Optional("line_search")) d.line_search = ls->Boolean();
  if (auto it = root.Optional("max_iterations"))
    d.max_iterations = static_cast<int>(it->Integer(1, 1000));
  if (auto tol = root.Optional("tolerance")) d.tolerance = tol->InRange(1e-4, 0.5);
  if (auto loss = root.Optional("loss")) {
    loss->ExpectObject({"kind", "scale"});
    d.loss = loss->Required("kind").Choice({"huber", "cauchy", "none"});
    if (auto scale = loss->Optional("scale")) d.loss_scale = scale->InRange(0.1, 100);
  }
  if (auto stages = root.Optional("stages")) {
    for (const char* key : {"parameters", "targets", "solver"})
      if (auto node = root.Optional(key))
        node->Fail(
            "a calibration in stages states its parameters, targets and solver in "
            "each stage");
    const std::size_t n = stages->ArraySize(1);
    for (std::size_t k = 0; k < n; ++k) {
      const JsonNode node = stages->At(k);
      node.ExpectObject({"name", "solver", "parameters", "targets"});
      CalibrationStage stage = ReadStage(node, d, e->scene);
      stage.pointer = node.path();
      stage.name = node.Required("name").String();
      for (const CalibrationStage& earlier : d.stages)
        if (earlier.name == stage.name)
          node.Required("name").Fail("a stage name is used once (also " +
                                     earlier.pointer + ")");
      d.stages.push_back(std::move(stage));
    }
  } else {
    d.stages.push_back(ReadStage(root, d, e->scene));
  }
  for (const CalibrationStage& stage : d.stages)
    CheckSegments(stage.targets, d.fatigue, path);
  e->input =
      core::ClonePtr<scene::KindInput>(std::make_unique<CalibrationDesign>(std::move(d)));
}

std::vector<std::string> CalibrationDesign::OwnParameters() const {
  std::vector<std::string> out;
  for (const CalibrationStage& stage : stages)
    for (const FitParameter& p : stage.parameters) out.push_back(p.name);
  return out;
}

void CalibrationDesign::ApplyOverrides(const scene::ParameterOverrides& o,
                                       scene::ExperimentFile* file) {
  for (CalibrationStage& stage : stages)
    for (FitParameter& p : stage.parameters)
      for (const auto& [name, value] : o.values) {
        if (name != p.name) continue;
        const double x = value.get<double>();  // a real: checked by LoadOverrides
        if (!(x >= p.lower && x <= p.upper))
          throw InputError(
              o.file, "/parameters/" + scene::PointerToken(name), scene::NumberText(x),
              fmt::format("a fitted parameter's override is its start, which "
                          "must lie within its bounds [{}, {}] ({}: {})",
                          scene::NumberText(p.lower), scene::NumberText(p.upper),
                          file->file, p.pointer));
        p.start = x;
        p.start_from = o.file;
      }
}

}  // namespace vahf::calibrate
