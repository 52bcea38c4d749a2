// A synthetic lab dataset (docs/calibration.md, "Synthetic data"): the model
// itself, at stated parameter values, plays the lab. Each operator assembles
// the scene's sequence `repetitions` times; every part trial becomes a row of
// trials.csv with its time plus a Gaussian reading error, rounded to the
// clock's resolution. A calibration that fits this dataset must recover the
// stated values within its intervals, and over many generated datasets its
// 95 % intervals must hold them about 95 % of the time: the test of the whole
// chain, lab format to Ceres covariance.
//
// Optionally, the lab works under several named conditions (each the scene,
// or a scene of its own, with the stated values and then the condition's
// own), and the scene's operator works an hour in segments whose attempts
// and successes become segments.csv (experiment::RunFatigue at the stated
// values), as a fatigue study records them.
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

// A working condition of the synthetic lab (as human_factors_groups has
// them): the generator's scene or its own, with the generator's stated
// values and then its own. Its rows carry its name.
struct SyntheticCondition {
  std::string name;
  std::string scene_path;  // its own scene; "" for the generator's
  scene::Scene scene;      // with the truth and its own values applied
  // Its own parameter values ("group/key", value), in file order.
  std::vector<std::pair<std::string, double>> parameters;
};

// The hour of work the synthetic lab records in segments.csv: `trials`
// cycles per segment of the fatigue design (0: no segments.csv).
struct SyntheticFatigue {
  scene::FatigueDesign design;
  int trials = 0;
};

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
  // Working conditions; empty: one, named `condition`, on `scene`.
  std::vector<SyntheticCondition> conditions;
  SyntheticFatigue fatigue;
};

// Reads a generator file (format "vahf-synthetic/1"; docs/calibration.md):
// one InputError naming file, pointer, value and rule for any fault.
SyntheticLabSpec LoadSyntheticLabSpec(const std::string& path);

// The dataset (in memory; data::WriteLabDataset writes it). Same spec: the
// same bits, whatever options.threads. Stream indices: condition c's
// operator k draws from (c x operators + k) x repetitions on; the hour of
// work of condition c, after every trial's, from c x (trials + pilot) on
// (its segments, then its pilot), so that no two records share a draw.
data::LabDataset GenerateSyntheticLab(const SyntheticLabSpec& spec,
                                      const experiment::RunnerOptions& options);

}  // namespace vahf::calibrate
