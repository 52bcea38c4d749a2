// The input of a calibrate experiment (docs/calibration.md): the parameters
// fitted, the lab summaries they are fitted to and the fit's settings, in
// stages, as its experiment file states them and its reader reads them.
#pragma once

#include <string>
#include <vector>

#include "vahf/scene/experiment_file.h"
#include "vahf/scene/json_reader.h"
#include "vahf/scene/shared_inputs.h"

namespace vahf::calibrate {

// A parameter a calibration fits: its name in the parameter table
// ("guidance/kappa", a real-valued one), where the search starts and the
// bounds it stays within (docs/calibration.md).
struct FitParameter {
  std::string name;
  double start = 0, lower = 0, upper = 0;
  std::string pointer;  // where the experiment file states it
  // The override file whose value is the start (`vahf run --overrides`: a
  // calibration started from its own calibrated.json, docs/calibration.md,
  // "A fixed point"); empty: the experiment file's start.
  std::string start_from;
};

// One stage of a calibration: parameters fitted to targets by a solver.
struct CalibrationStage {
  std::string name;     // the file's stage name; "" for a file of one stage
  std::string pointer;  // where the file states it ("" for a file of one stage)
  // "levenberg_marquardt" (Ceres) or "golden_section" (one parameter: GSL's bracketed
  // golden-section minimisation of the same cost, for objectives that are piecewise
  // constant in the parameter; Ceres then gives the covariance).
  std::string solver = "levenberg_marquardt";
  std::vector<FitParameter> parameters;
  std::vector<scene::FitTarget> targets;
};

// Ceres least squares of parameters to a lab dataset's summaries
// (calibrate/calibration.h), in stages: each stage starts from the scene with
// every earlier stage's estimates (a sequential calibration).
struct CalibrationDesign : scene::KindInputOf<CalibrationDesign> {
  std::string lab_path;  // the lab dataset's manifest
  // The lab dataset's files (data::LabDatasetFiles): a resumed calibration
  // checks them against its journal.
  std::vector<std::string> InputFiles() const override;
  std::vector<CalibrationStage> stages;  // at least one
  // Robust loss on the whitened residuals: "huber", "cauchy" or "none"; its
  // scale in standard deviations (residuals beyond it are down-weighted).
  std::string loss = "huber";
  double loss_scale = 3.0;
  double relative_step = 0.05;  // of each parameter's value, central differences
  // Other sets of virtual people the estimate is re-weighed on, for its
  // Monte Carlo spread (calibration.h, FittedParameter::mc_sd); 0: none.
  int noise_replicates = 4;
  // Levenberg-Marquardt stages: "wald" gives each identified parameter the
  // interval of the covariance at the estimate only; "profile" also gives
  // its profile-likelihood interval, the others re-fitted at each value
  // (profile_likelihood.h), which follows a curved valley where the Wald
  // interval does not, at the cost of a few re-fits per end.
  std::string intervals = "wald";
  // Levenberg-Marquardt stages: Ceres' projected line search on the bounds
  // after every step (true), or the step alone, projected onto them
  // (false). Each line-search step differences a whole Jacobian (2 p + 1
  // design evaluations): it finds better points where the fit runs along a
  // bound, and costs most of the evaluations where it stays inside
  // (docs/calibration.md, Solvers).
  bool line_search = true;
  int max_iterations =
      30;  // Levenberg-Marquardt (or golden-section) iterations per round
  // golden_section: the search stops when the bracket is narrower than this fraction
  // of the estimate.
  double tolerance = 0.02;
  // The hour of work that segment targets are read from (the file's
  // "fatigue", as the fatigue kind reads it).
  scene::FatigueDesign fatigue;

  // An override file's value for a fitted parameter is its start; it must
  // lie within the stage's bounds, else an InputError names the override
  // file and the bounds.
  void ApplyOverrides(const scene::ParameterOverrides& o,
                      scene::ExperimentFile* file) override;
  // The fitted parameters: an override of one is its start, and the scene
  // keeps its own value, so that a calibration started from its own
  // calibrated.json runs every stage as the first run did.
  std::vector<std::string> OwnParameters() const override;
};

// calibrate: "lab", "fatigue", the fit's parameters, targets, stages and settings.
void ReadCalibration(const scene::JsonNode& root, const std::string& path,
                     scene::ExperimentFile* e);

}  // namespace vahf::calibrate
