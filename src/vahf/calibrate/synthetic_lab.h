// A synthetic lab dataset (docs/calibration.md, "Synthetic data"): the model
// itself, at stated parameter values, plays the lab. Each operator assembles
// the scene's sequence `repetitions` times; every part trial becomes a row of
// trials.csv with its time plus a Gaussian reading error, rounded to the
// clock's resolution. A calibration that fits this dataset must recover the
// stated values within its intervals, and over many generated datasets its
// 95 % intervals must hold them about 95 % of the time: the test of the whole
// chain, lab format to Ceres covariance.
//
// The lab's trials use their own seed: a calibration with another seed sees
// other draws, as it would see other people.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "vahf/data/lab_dataset.h"
#include "vahf/experiment/runner.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/scene.h"
#include "vahf/scene/shared_inputs.h"

namespace vahf::calibrate {

struct SyntheticLabSpec {
  std::string file;  // where it was read from, for provenance
  std::string name, description;
  std::string scene_path;
  scene::Scene scene;  // with `truth` applied
  // The stated parameter values ("group/key", value), in file order.
  std::vector<std::pair<std::string, double>> truth;
  // The stated choices ("learning/model", "power_law"), in file order.
  std::vector<std::pair<std::string, std::string>> choices;
  std::vector<scene::OperatorEntry> operators;  // at least one
  int repetitions = 10;
  std::uint64_t seed = 1;
  double time_sd = 0;          // s, sd of the Gaussian reading error
  double time_resolution = 0;  // s, recorded times are rounded to it; 0: not rounded
  std::string condition = "synthetic";
};

// Reads a generator file (format "vahf-synthetic/1"; docs/calibration.md):
// one InputError naming file, pointer, value and rule for any fault.
SyntheticLabSpec LoadSyntheticLabSpec(const std::string& path);

// The dataset (in memory; data::WriteLabDataset writes it). Same spec: the
// same bits, whatever options.threads.
data::LabDataset GenerateSyntheticLab(const SyntheticLabSpec& spec,
                                      const experiment::RunnerOptions& options);

}  // namespace vahf::calibrate
