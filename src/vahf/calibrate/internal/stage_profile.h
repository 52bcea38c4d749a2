// The profile-likelihood intervals of a Levenberg-Marquardt stage's
// parameters (docs/calibration.md, Profile intervals): each profile value
// re-fits the other identified parameters by secant steps
// (profile_likelihood.h). Internal to calibrate/.
#pragma once
#include <string>
#include <vector>

#include "vahf/calibrate/calibration.h"
#include "vahf/calibrate/internal/virtual_model.h"

namespace vahf::calibrate {

// Each identified parameter's 95 % profile interval at the estimate x, on
// the weights `sigma` of its covariance (out's covariance and whitened
// Jacobian): sets `fitted`'s profile fields and out's least rise, and
// reports one line a parameter to `progress`.
void ProfileIntervals(VirtualModel& model, const CalibrationSpec& spec,
                      const StageSpec& stage, const std::vector<Target>& targets,
                      const std::vector<double>& sigma, const std::vector<double>& x,
                      const std::string& prefix, const CalibrationProgress& progress,
                      CalibrationResult* out, std::vector<FittedParameter>* fitted);

}  // namespace vahf::calibrate
