#include "vahf/report/calibration_section.h"

#include <fmt/format.h>

#include <cmath>

#include "vahf/scene/overrides.h"

namespace vahf::report {
namespace {

double Sd(double variance) { return std::sqrt(variance); }

std::string Number(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : "-"; }

}  // namespace

nlohmann::json OverridesJson(const scene::ExperimentFile& file,
                             const calibrate::CalibrationResult& result) {
  nlohmann::json params = nlohmann::json::object();
  for (const calibrate::FittedParameter& p : result.parameters) params[p.name] = p.estimate;
  return {{"format", scene::kOverridesFormat},
          // The experiment's name, not its path as typed: the file is a result.
          {"source", fmt::format("calibrate experiment '{}' (vahf run)", file.name)},
          {"parameters", params}};
}

Section CalibrationSection(const scene::ExperimentFile& file, const data::LabDataset& lab,
                           const calibrate::CalibrationResult& r) {
  Section out;
  out.kind = "calibrate";
  const scene::CalibrationDesign& d = file.calibration;

  Table params({"parameter", "start", "lower", "upper", "estimate", "standard_error",
                "ci_lower", "ci_upper", "at_bound"});
  nlohmann::json params_json = nlohmann::json::array();
  std::string md = fmt::format(
      "## Calibration against {}\n\n{}\n\nLab dataset `{}`: {} (provenance: {}). "
      "Ceres least squares of {} parameter(s) to {} target(s), each residual whitened by "
      "the lab's and the virtual statistic's standard errors; {} loss (scale {} sd); "
      "central differences over {} of each value on common random numbers; {} design "
      "evaluations, {} round(s) of re-weighting; {}.\n\n"
      "| parameter | start | bounds | estimate | standard error | 95 % interval |\n"
      "| --- | --- | --- | --- | --- | --- |\n",
      lab.name, file.description, file.calibration.lab_path, lab.description,
      lab.provenance.value("source", ""), r.parameters.size(), r.targets.size(), d.loss,
      d.loss_scale, d.relative_step, r.evaluations, r.rounds,
      r.converged ? "Ceres converged" : "**Ceres did not report convergence**");
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const calibrate::FittedParameter& p = r.parameters[i];
    const scene::FitParameter& spec = d.parameters[i];
    // Ceres' covariance ignores the bounds: at a bound the interval is the
    // curvature's, not a confidence statement (docs/calibration.md).
    const bool at_bound = p.estimate <= spec.lower || p.estimate >= spec.upper;
    params.AddRow({p.name, p.start, spec.lower, spec.upper, p.estimate, p.standard_error,
                   p.ci.lower, p.ci.upper, std::int64_t{at_bound ? 1 : 0}});
    params_json.push_back({{"name", p.name},
                           {"estimate", p.estimate},
                           {"standard_error", p.standard_error},
                           {"ci", {p.ci.lower, p.ci.upper}},
                           {"at_bound", at_bound}});
    md += fmt::format("| `{}` | {} | [{}, {}] | **{}** | {} | [{}, {}]{} |\n", p.name,
                      Number(p.start), Number(spec.lower), Number(spec.upper),
                      Number(p.estimate), Number(p.standard_error), Number(p.ci.lower),
                      Number(p.ci.upper), at_bound ? " (at a bound)" : "");
  }
  if (!r.covariance_ok)
    md += "\nThe covariance is rank deficient (a parameter the targets do not determine): "
          "no standard errors.\n";

  Table targets({"target", "unit", "lab", "lab_se", "lab_n", "virtual_start",
                 "virtual_start_se", "virtual_fitted", "virtual_fitted_se", "virtual_n",
                 "residual"});
  md += "\n| target | lab (se, n) | virtual at start (se) | virtual at the fit (se) | "
        "residual (sd) |\n| --- | --- | --- | --- | --- |\n";
  std::string data;
  for (std::size_t i = 0; i < r.targets.size(); ++i) {
    const calibrate::FittedTarget& t = r.targets[i];
    targets.AddRow({t.target.label, t.target.unit, t.target.lab.value, Sd(t.target.lab.variance),
                    std::int64_t{t.target.lab.n}, t.start.value, Sd(t.start.variance),
                    t.fitted.value, Sd(t.fitted.variance), std::int64_t{t.fitted.n},
                    t.residual});
    md += fmt::format("| {} ({}) | {} ({}, {}) | {} ({}) | {} ({}) | {:.2f} |\n",
                      t.target.label, t.target.unit, Number(t.target.lab.value),
                      Number(Sd(t.target.lab.variance)), t.target.lab.n, Number(t.start.value),
                      Number(Sd(t.start.variance)), Number(t.fitted.value),
                      Number(Sd(t.fitted.variance)), t.residual);
    // x, label, lab, lab half-width, start, start hw, fit, fit hw (95 %)
    data += fmt::format("{} \"{}\" {} {} {} {} {} {}\n", i, t.target.label, t.target.lab.value,
                        1.96 * Sd(t.target.lab.variance), t.start.value,
                        1.96 * Sd(t.start.variance), t.fitted.value,
                        1.96 * Sd(t.fitted.variance));
  }
  md += fmt::format("\nThe fitted values are in `{}`, a parameter-override file: "
                    "`vahf run EXPERIMENT --overrides {}` runs any experiment with them.\n\n"
                    "Ceres:\n\n```\n{}```\n\n<details><summary>Ceres' full report (last "
                    "round)</summary>\n\n```\n{}```\n\n</details>\n\n",
                    kOverridesFile, kOverridesFile, r.ceres_brief, r.ceres_full);

  Table covariance({"row", "column", "covariance"});
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    for (std::size_t j = 0; j < r.parameters.size(); ++j)
      covariance.AddRow({r.parameters[i].name, r.parameters[j].name,
                         static_cast<double>(r.covariance(static_cast<Eigen::Index>(i),
                                                          static_cast<Eigen::Index>(j)))});

  out.tables.emplace_back("calibrate_parameters.csv", std::move(params));
  out.tables.emplace_back("calibrate_targets.csv", std::move(targets));
  out.tables.emplace_back("calibrate_covariance.csv", std::move(covariance));
  out.files.emplace_back(kOverridesFile, OverridesJson(file, r).dump(1) + "\n");
  out.summary = {{"parameters", params_json},
                 {"converged", r.converged},
                 {"covariance_ok", r.covariance_ok},
                 {"evaluations", r.evaluations},
                 {"rounds", r.rounds},
                 {"final_cost", r.final_cost},
                 {"claims", nlohmann::json::array()}};
  out.markdown = md;
  out.plots.push_back(
      {"plots/calibrate_targets.png",
       "Each target: the lab's value and the virtual one at the start and at the fit "
       "(95 % intervals)",
       "$d << EOD\n" + data +
           "EOD\nset title 'Lab against virtual, before and after the fit'\n"
           "set ylabel 'value (the target unit: s for times, 1 for rates)'\n"
           "set xrange [-0.5:" + std::to_string(r.targets.size()) + "-0.5]\n"
           "set grid y\nset key outside bottom center horizontal\n"
           "plot $d using ($1-0.15):3:4:xtic(2) with yerrorbars pt 7 title 'lab', "
           "'' using 1:5:6 with yerrorbars pt 6 title 'virtual at start', "
           "'' using ($1+0.15):7:8 with yerrorbars pt 5 title 'virtual at the fit'\n"});
  return out;
}

}  // namespace vahf::report
