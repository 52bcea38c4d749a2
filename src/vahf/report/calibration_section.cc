#include "vahf/report/calibration_section.h"

#include <fmt/format.h>

#include <cmath>

#include "vahf/scene/overrides.h"
#include "vahf/scene/parameter_table.h"

namespace vahf::report {
namespace {

double Sd(double variance) { return std::sqrt(variance); }

std::string Number(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : "-"; }

}  // namespace

nlohmann::json OverridesJson(const scene::ExperimentFile& file,
                             const std::vector<calibrate::CalibrationResult>& stages) {
  nlohmann::json params = nlohmann::json::object();
  for (const calibrate::CalibrationResult& r : stages)
    for (const calibrate::FittedParameter& p : r.parameters) params[p.name] = p.estimate;
  return {{"format", scene::kOverridesFormat},
          // The experiment's name, not its path as typed: the file is a result.
          {"source", fmt::format("calibrate experiment '{}' (vahf run)", file.name)},
          {"parameters", params}};
}

Section CalibrationSection(const scene::ExperimentFile& file, const data::LabDataset& lab,
                           const std::vector<calibrate::CalibrationResult>& stages) {
  Section out;
  out.kind = "calibrate";
  const scene::CalibrationDesign& d = file.calibration;
  int evaluations = 0;
  for (const calibrate::CalibrationResult& r : stages) evaluations += r.evaluations;

  Table params({"stage", "parameter", "unit", "scene_value", "start", "lower", "upper",
                "estimate", "standard_error", "ci_lower", "ci_upper", "at_bound",
                "profile_lower", "profile_upper", "profile_open_lower",
                "profile_open_upper"});
  Table targets({"stage", "target", "unit", "lab", "lab_se", "lab_n", "virtual_start",
                 "virtual_start_se", "virtual_fitted", "virtual_fitted_se", "virtual_n",
                 "residual"});
  Table covariance({"stage", "row", "column", "covariance"});
  nlohmann::json params_json = nlohmann::json::array();
  nlohmann::json stages_json = nlohmann::json::array();
  std::string md = fmt::format(
      "## Calibration against {}\n\n{}\n\nLab dataset `{}`: {} (provenance: {}). "
      "Each residual is whitened by the lab's and the virtual statistic's standard "
      "errors; "
      "{} loss (scale {} sd); central differences over {} of each value on common random "
      "numbers; {} design evaluations in {} stage(s).{}\n",
      lab.name, file.description, file.calibration.lab_path, lab.description,
      lab.provenance.value("source", ""), d.loss, d.loss_scale, d.relative_step,
      evaluations, stages.size(),
      stages.size() > 1
          ? " Each stage starts from the scene with the earlier stages' estimates; its "
            "intervals are conditional on them (an earlier estimate's uncertainty is not "
            "carried into a later stage's interval)."
          : "");
  std::string data;
  std::size_t row = 0;
  for (std::size_t k = 0; k < stages.size(); ++k) {
    const calibrate::CalibrationResult& r = stages[k];
    const scene::CalibrationStage& spec = d.stages[k];
    const std::string stage = r.stage.empty() ? "1" : r.stage;
    const std::string solver = r.solver == "golden_section"
                                   ? fmt::format(
                                         "a bracketed golden-section search (GSL) to {} "
                                         "of the value, then Ceres' "
                                         "covariance at the estimate",
                                         d.tolerance)
                                   : "Ceres' Levenberg-Marquardt";
    md += fmt::format(
        "\n### {}\n\n{} parameter(s) to {} target(s) by {}; {} design evaluations, {} "
        "round(s) of re-weighting, {:.0f} s; {}.\n\n"
        "| parameter | unit | the scene's value | start | bounds | estimate | standard "
        "error | "
        "95 % interval | 95 % profile interval |\n| --- | --- | --- | --- | --- | --- | "
        "--- | --- "
        "| --- |\n",
        r.stage.empty() ? "Fit" : "Stage: " + r.stage, r.parameters.size(),
        r.targets.size(), solver, r.evaluations, r.rounds, r.seconds,
        r.converged ? "converged" : "**the solver did not report convergence**");
    for (std::size_t i = 0; i < r.parameters.size(); ++i) {
      const calibrate::FittedParameter& p = r.parameters[i];
      const scene::FitParameter& ps = spec.parameters[i];
      // Ceres' covariance ignores the bounds: at a bound the interval is the
      // curvature's, not a confidence statement (docs/calibration.md).
      const bool at_bound = p.estimate <= ps.lower || p.estimate >= ps.upper;
      const std::string unit = scene::FindParam(p.name)->unit;
      const double nan = std::nan("");
      params.AddRow(
          {stage, p.name, unit, p.scene_value, p.start, ps.lower, ps.upper, p.estimate,
           p.standard_error, p.ci.lower, p.ci.upper, std::int64_t{at_bound ? 1 : 0},
           p.has_profile ? p.profile.lower : nan, p.has_profile ? p.profile.upper : nan,
           std::int64_t{p.profile_open_lower ? 1 : 0},
           std::int64_t{p.profile_open_upper ? 1 : 0}});
      params_json.push_back(
          {{"stage", stage},
           {"name", p.name},
           {"unit", unit},
           {"scene_value", p.scene_value},
           {"estimate", p.estimate},
           {"standard_error", p.standard_error},
           {"ci", {p.ci.lower, p.ci.upper}},
           {"at_bound", at_bound},
           {"profile_ci", p.has_profile ? nlohmann::json{p.profile.lower, p.profile.upper}
                                        : nlohmann::json(nullptr)},
           {"profile_open", {p.profile_open_lower, p.profile_open_upper}}});
      const std::string profile =
          p.has_profile
              ? fmt::format("[{}{}, {}{}]", p.profile_open_lower ? "open at " : "",
                            Number(p.profile.lower), Number(p.profile.upper),
                            p.profile_open_upper ? ", open" : "")
              : "-";
      md += fmt::format(
          "| `{}` | {} | {} | {} | [{}, {}] | **{}** | {} | [{}, {}]{} | {} |\n", p.name,
          unit, Number(p.scene_value), Number(p.start), Number(ps.lower),
          Number(ps.upper), Number(p.estimate), Number(p.standard_error),
          Number(p.ci.lower), Number(p.ci.upper), at_bound ? " (at a bound)" : "",
          profile);
    }
    if (r.solver == "golden_section")
      md +=
          "\nThe profile interval holds the values whose cost (1/2 the sum of the "
          "whitened "
          "squared residuals, on common random numbers) is within chi^2_1(0.95) / 2 = "
          "1.92 "
          "of the estimate's: it needs no slope, so it holds where the cost is a step "
          "function and the standard error, from Ceres' slope at the estimate, does not; "
          "an "
          "end that reaches the parameter's bound is open there (docs/calibration.md).\n";
    if (!r.covariance_ok)
      md +=
          "\nThe covariance is rank deficient (the targets do not move within a "
          "central-difference step of the estimate, or a parameter they do not "
          "determine): no standard errors.\n";

    md +=
        "\n| target | lab (se, n) | virtual at start (se) | virtual at the fit (se) | "
        "residual (sd) |\n| --- | --- | --- | --- | --- |\n";
    for (const calibrate::FittedTarget& t : r.targets) {
      const double lab_var = calibrate::LabVariance(t.target.lab, t.fitted);
      targets.AddRow({stage, t.target.label, t.target.unit, t.target.lab.value,
                      Sd(lab_var), std::int64_t{t.target.lab.n}, t.start.value,
                      Sd(t.start.variance), t.fitted.value, Sd(t.fitted.variance),
                      std::int64_t{t.fitted.n}, t.residual});
      md +=
          fmt::format("| {} ({}) | {} ({}{}, {}) | {} ({}) | {} ({}) | {:.2f} |\n",
                      t.target.label, t.target.unit, Number(t.target.lab.value),
                      Number(Sd(lab_var)), t.target.lab.single_draw ? ": one draw" : "",
                      t.target.lab.n, Number(t.start.value), Number(Sd(t.start.variance)),
                      Number(t.fitted.value), Number(Sd(t.fitted.variance)), t.residual);
      // x, label, lab, lab half-width, start, start hw, fit, fit hw (95 %)
      data += fmt::format("{} \"{}\" {} {} {} {} {} {}\n", row++, t.target.label,
                          t.target.lab.value, 1.96 * Sd(lab_var), t.start.value,
                          1.96 * Sd(t.start.variance), t.fitted.value,
                          1.96 * Sd(t.fitted.variance));
    }
    md += fmt::format("\nSolver:\n\n```\n{}```\n", r.ceres_brief);
    if (!r.search_log.empty())
      md += fmt::format(
          "\n<details><summary>The bracketed search, step by step</summary>"
          "\n\n```\n{}```\n\n</details>\n",
          r.search_log);
    if (!r.ceres_full.empty())
      md += fmt::format(
          "\n<details><summary>Ceres' full report (last round)</summary>"
          "\n\n```\n{}```\n\n</details>\n",
          r.ceres_full);
    for (std::size_t i = 0; i < r.parameters.size(); ++i)
      for (std::size_t j = 0; j < r.parameters.size(); ++j)
        covariance.AddRow(
            {stage, r.parameters[i].name, r.parameters[j].name,
             static_cast<double>(r.covariance(static_cast<Eigen::Index>(i),
                                              static_cast<Eigen::Index>(j)))});
    stages_json.push_back({{"stage", stage},
                           {"solver", r.solver},
                           {"converged", r.converged},
                           {"covariance_ok", r.covariance_ok},
                           {"evaluations", r.evaluations},
                           {"rounds", r.rounds},
                           {"final_cost", r.final_cost}});
  }
  md += fmt::format(
      "\nThe fitted values are in `{}`, a parameter-override file: "
      "`vahf run EXPERIMENT --overrides {}` runs any experiment with them.\n\n",
      kOverridesFile, kOverridesFile);

  out.tables.emplace_back("calibrate_parameters.csv", std::move(params));
  out.tables.emplace_back("calibrate_targets.csv", std::move(targets));
  out.tables.emplace_back("calibrate_covariance.csv", std::move(covariance));
  out.files.emplace_back(kOverridesFile, OverridesJson(file, stages).dump(1) + "\n");
  out.summary = {{"parameters", params_json},
                 {"stages", stages_json},
                 {"evaluations", evaluations},
                 {"claims", nlohmann::json::array()}};
  out.markdown = md;
  out.plots.push_back(
      {"plots/calibrate_targets.png",
       "Each target: the lab's value and the virtual one at the start and at the fit "
       "(95 % intervals)",
       "$d << EOD\n" + data +
           "EOD\nset title 'Lab against virtual, before and after the fit'\n"
           "set ylabel 'value (the target unit: s for times, 1 for rates)'\n"
           "set xrange [-0.5:" +
           std::to_string(row) +
           "-0.5]\n"
           "set grid y\nset key outside bottom center horizontal\n"
           "plot $d using ($1-0.15):3:4:xtic(2) with yerrorbars pt 7 title 'lab', "
           "'' using 1:5:6 with yerrorbars pt 6 title 'virtual at start', "
           "'' using ($1+0.15):7:8 with yerrorbars pt 5 title 'virtual at the fit'\n"});
  return out;
}

}  // namespace vahf::report
