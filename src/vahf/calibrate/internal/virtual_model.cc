#include "vahf/calibrate/internal/virtual_model.h"

#include <ceres/loss_function.h>

namespace vahf::calibrate {

void SetParameters(const std::vector<ParameterSpec>& params, const double* x,
                   scene::Scene* scene) {
  for (std::size_t i = 0; i < params.size(); ++i) {
    const scene::ParamSpec* spec = scene::FindParam(params[i].name);
    VAHF_CHECK(spec && spec->real, "fitted parameters are real-valued table entries");
    spec->real(scene->params) = x[i];
  }
}

std::string VectorText(const std::vector<ParameterSpec>& params, const double* x) {
  std::string out;
  for (std::size_t i = 0; i < params.size(); ++i)
    out += fmt::format("{}{} {:.6g}", i ? ", " : "", params[i].name, x[i]);
  return out;
}

ceres::LossFunction* MakeLoss(const CalibrationSpec& spec) {
  if (spec.loss == "huber") return new ceres::HuberLoss(spec.loss_scale);
  if (spec.loss == "cauchy") return new ceres::CauchyLoss(spec.loss_scale);
  return nullptr;  // "none": plain least squares
}

double Cost(VirtualModel& model, const std::vector<Target>& targets,
            const std::vector<double>& sigma, const CalibrationSpec& spec,
            const double* x) {
  const std::vector<Statistic>& v = model.At(x);
  const std::unique_ptr<ceres::LossFunction> loss(MakeLoss(spec));
  double cost = 0;
  for (std::size_t i = 0; i < targets.size(); ++i) {
    if (!std::isfinite(v[i].value)) return std::nan("");  // no sample
    const double r = (v[i].value - targets[i].lab.value) / sigma[i];
    double rho[3] = {r * r, 1, 0};
    if (loss) loss->Evaluate(r * r, rho);
    cost += 0.5 * rho[0];
  }
  return cost;
}

}  // namespace vahf::calibrate
