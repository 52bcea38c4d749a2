#include "vahf/report/calibration_section.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "vahf/report/figure.h"
#include "vahf/report/markdown.h"
#include "vahf/scene/overrides.h"
#include "vahf/scene/parameter_table.h"

namespace vahf::report {
namespace {

double Sd(double variance) { return std::sqrt(variance); }

std::string Number(double x) { return std::isfinite(x) ? fmt::format("{:.4g}", x) : "-"; }

// What every stage adds to: the three tables, the summary's lists and the
// plot's rows (one per target, numbered across the stages).
struct CalibrationTables {
  Table params{{"stage",
                "parameter",
                "unit",
                "scene_value",
                "start",
                "lower",
                "upper",
                "estimate",
                "standard_error",
                "ci_lower",
                "ci_upper",
                "at_bound",
                "profile_lower",
                "profile_upper",
                "profile_open_lower",
                "profile_open_upper",
                "identified",
                "edge_lower",
                "edge_upper",
                "rise_lower",
                "rise_upper",
                "monte_carlo_sd"}};
  Table targets{{"stage", "target", "unit", "lab", "lab_se", "lab_n", "virtual_start",
                 "virtual_start_se", "virtual_fitted", "virtual_fitted_se", "virtual_n",
                 "residual"}};
  Table covariance{{"stage", "row", "column", "covariance", "correlation"}};
  nlohmann::json params_json = nlohmann::json::array();
  nlohmann::json stages_json = nlohmann::json::array();
  std::vector<DataRow> plot_rows;
  Table scan{{"stage", "parameter", "value", "cost_rise"}};
  // Per scanned parameter: its label and rows (position from the estimate,
  // -1 at the lower end of its range and 1 at the upper; the cost's rise).
  std::vector<std::pair<std::string, std::vector<DataRow>>> scan_rows;
  // The same for the profile points ("intervals": "profile"), the others
  // re-fitted at each.
  Table profile{{"stage", "parameter", "value", "cost_rise"}};
  std::vector<std::pair<std::string, std::vector<DataRow>>> profile_rows;
  // Targets by repetition (the learning curve): repetition, lab value and
  // half-width, virtual at the fit and half-width (95 %); one series a stage
  // and target.
  std::vector<std::pair<std::string, std::vector<DataRow>>> learning_rows;
  std::string markdown;
};

std::string Intro(const scene::ExperimentFile& file, const data::LabDataset& lab,
                  const std::vector<calibrate::CalibrationResult>& stages,
                  int evaluations) {
  const calibrate::CalibrationDesign& d = file.Input<calibrate::CalibrationDesign>();
  bool pooled = false;
  for (const auto& stage : d.stages)
    for (const auto& t : stage.targets) pooled = pooled || t.pooled_variance;
  return fmt::format(
      "## Calibration against {}\n\n{}\n\nLab dataset `{}`: {} (provenance: {}). "
      "Each residual is whitened by the lab's and the virtual statistic's standard "
      "errors{}; {} loss (scale {} sd); central differences over {} of each value on "
      "common random numbers; {} design evaluations in {} stage(s).{}\n",
      lab.name, file.description, d.lab_path, lab.description,
      lab.provenance.value("source", ""),
      pooled ? " (for a target with `\"variance\": \"pooled\"`, each operator's from "
               "the variance pooled over the target's operators, on each side)"
             : "",
      d.loss, d.loss_scale, d.relative_step, evaluations, stages.size(),
      stages.size() > 1
          ? " Each stage starts from the scene with the earlier stages' estimates; its "
            "intervals are conditional on them (an earlier estimate's uncertainty is not "
            "carried into a later stage's interval)."
          : "");
}

std::string StageHeading(const calibrate::CalibrationResult& r,
                         const calibrate::CalibrationDesign& d) {
  const std::string solver =
      r.solver == "golden_section"
          ? fmt::format(
                "a bracketed golden-section search (GSL) to {} of the value, "
                "then Ceres' covariance at the estimate",
                d.tolerance)
          : "Ceres' Levenberg-Marquardt";
  return fmt::format(
      "\n### {}\n\n{} parameter(s) to {} target(s) by {}; {} design evaluations, {} "
      "round(s) of re-weighting, {:.0f} s; {}.\n\n",
      r.stage.empty() ? "Fit" : "Stage: " + r.stage, r.parameters.size(),
      r.targets.size(), solver, r.evaluations, r.rounds, r.seconds,
      r.converged ? "converged" : "**the solver did not report convergence**");
}

std::string ProfileText(const calibrate::FittedParameter& p) {
  if (!p.has_profile) return "-";
  return fmt::format("[{}{}, {}{}]{}", p.profile_open_lower ? "open at " : "",
                     Number(p.profile.lower), Number(p.profile.upper),
                     p.profile_open_upper ? ", open" : "",
                     p.profile_reached ? "" : " (an end not reached: wider)");
}

// The whitened Jacobian's rank and conditioning, how it was differenced, and
// the estimates' correlations.
std::string IdentifiabilityText(const calibrate::CalibrationResult& r) {
  const std::size_t p = r.parameters.size();
  std::string values;
  for (Eigen::Index k = 0; k < r.rank.singular_values.size(); ++k)
    values += fmt::format("{}{:.3g}", k ? ", " : "", r.rank.singular_values(k));
  std::string md = fmt::format(
      "\n\nIdentifiability: the whitened Jacobian at the estimate, its columns scaled by "
      "the estimates, has rank {} of {} (singular values {}; a direction counts as flat "
      "below {:g} of the largest){}. Its difference columns (one per target and "
      "parameter at each Jacobian): {} central, {} one-sided at the edge of the valid "
      "region, {} with a shortened step; {} point(s) the solver asked for lay outside "
      "it (bounds or a rule such as D1 < D2 < D3) and were refused.\n",
      r.rank.rank, p, values, calibrate::kRankTolerance,
      r.rank.rank > 0 ? fmt::format(", condition number {:.3g}", r.rank.condition) : "",
      r.differences.central, r.differences.one_sided, r.differences.shortened, r.refused);
  if (r.noise_replicates > 0)
    md += fmt::format(
        "\nThe Monte Carlo column is the estimate's spread over {} other sets of "
        "virtual people (the cycles after the fit's): on each, the Gauss-Newton step "
        "from the estimate its residuals call for, root mean square. It is the part of "
        "the standard error the virtual trials' noise makes; more `trials` shrink it "
        "as their square root.\n",
        r.noise_replicates);
  if (p < 2) return md;
  std::vector<std::string> header = {"correlation"};
  for (const calibrate::FittedParameter& f : r.parameters) header.push_back(f.name);
  MarkdownTable corr{header};
  for (std::size_t i = 0; i < p; ++i) {
    std::vector<std::string> row = {"`" + r.parameters[i].name + "`"};
    for (std::size_t j = 0; j < p; ++j) {
      const double c =
          r.correlation(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j));
      row.push_back(std::isfinite(c) ? fmt::format("{:.2f}", c) : "-");
    }
    corr.AddRow(row);
  }
  return md + "\n" + ToMarkdown(corr);
}

// An identified parameter whose cost, alone, rises less than the 95 %
// profile threshold to one end of its range: the data bound it on one side.
std::string OpenSide(const calibrate::FittedParameter& p) {
  const double rise = calibrate::ProfileRise();
  if (p.rise_lower < rise)
    return fmt::format("; the cost rises {:.2g} to {}: not bounded below it",
                       p.rise_lower, Number(p.edge_lower));
  if (p.rise_upper < rise)
    return fmt::format("; the cost rises {:.2g} to {}: not bounded above it",
                       p.rise_upper, Number(p.edge_upper));
  return "";
}

// The stage's fitted parameters: table rows, summary entries and Markdown.
// For each parameter started at an override file's value (its own earlier
// estimate): whether the fit returned to it within the solver's tolerance.
std::string FixedPointText(const calibrate::CalibrationResult& r) {
  std::string out;
  for (const calibrate::FittedParameter& p : r.parameters) {
    if (p.start_from.empty()) continue;
    const bool holds = p.fixed_point_change <= p.fixed_point_tolerance;
    out += fmt::format(
        "\n- **A fixed point{}**: `{}` started at {} from `{}` and ended at {}, {:.3g} "
        "away, {} the solver's tolerance {:.3g} ({}).",
        holds ? "" : ": no", p.name, Number(p.start), p.start_from, Number(p.estimate),
        p.fixed_point_change, holds ? "within" : "beyond", p.fixed_point_tolerance,
        r.solver == "golden_section"
            ? "the stage's `tolerance` times the estimate"
            : "the larger of a tenth of its standard error and Ceres' parameter "
              "tolerance; its weights, evaluated at its start, settle to 10 %");
  }
  return out.empty() ? out : out + "\n";
}

void AddParameters(const std::string& stage, const calibrate::CalibrationResult& r,
                   const calibrate::CalibrationStage& spec, CalibrationTables* t) {
  MarkdownTable md{{"parameter", "unit", "the scene's value", "start", "bounds",
                    "estimate", "standard error", "of which Monte Carlo", "95 % interval",
                    "95 % profile interval"}};
  for (std::size_t i = 0; i < r.parameters.size(); ++i) {
    const calibrate::FittedParameter& p = r.parameters[i];
    const calibrate::FitParameter& ps = spec.parameters[i];
    // Ceres' covariance ignores the bounds: at a bound the interval is the
    // curvature's, not a confidence statement (docs/calibration.md).
    const bool at_bound = p.estimate <= ps.lower || p.estimate >= ps.upper;
    const std::string unit = scene::FindParam(p.name)->unit;
    const double nan = std::nan("");
    t->params.AddRow({stage,
                      p.name,
                      unit,
                      p.scene_value,
                      p.start,
                      ps.lower,
                      ps.upper,
                      p.estimate,
                      p.standard_error,
                      p.ci.lower,
                      p.ci.upper,
                      std::int64_t{at_bound ? 1 : 0},
                      p.has_profile ? p.profile.lower : nan,
                      p.has_profile ? p.profile.upper : nan,
                      std::int64_t{p.profile_open_lower ? 1 : 0},
                      std::int64_t{p.profile_open_upper ? 1 : 0},
                      std::int64_t{p.identified ? 1 : 0},
                      p.edge_lower,
                      p.edge_upper,
                      p.rise_lower,
                      p.rise_upper,
                      p.mc_sd});
    t->params_json.push_back(
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
         {"profile_open", {p.profile_open_lower, p.profile_open_upper}},
         {"identified", p.identified},
         {"not_identified_why", p.not_identified_why}});
    // Only a start an override file gave has one: no other run's file moves.
    if (!p.start_from.empty())
      t->params_json.back()["fixed_point"] = {
          {"start_from", p.start_from},
          {"start", p.start},
          {"change", p.fixed_point_change},
          {"tolerance", p.fixed_point_tolerance},
          {"holds", p.fixed_point_change <= p.fixed_point_tolerance}};
    md.AddRow({"`" + p.name + "`", unit, Number(p.scene_value), Number(p.start),
               fmt::format("[{}, {}]", Number(ps.lower), Number(ps.upper)),
               "**" + Number(p.estimate) + "**", Number(p.standard_error),
               Number(p.mc_sd),
               p.identified
                   ? fmt::format("[{}, {}]{}{}", Number(p.ci.lower), Number(p.ci.upper),
                                 at_bound ? " (at a bound)" : "", OpenSide(p))
                   : "**not identified**",
               ProfileText(p)});
  }
  t->markdown += ToMarkdown(md);
  t->markdown += FixedPointText(r);
  for (const calibrate::FittedParameter& p : r.parameters)
    if (!p.identified)
      t->markdown += fmt::format("\n- `{}` is **not identified**: {}.", p.name,
                                 p.not_identified_why);
  t->markdown += IdentifiabilityText(r);
}

// The stage's targets, lab beside virtual: table rows, Markdown, plot rows.
// A target by repetition on its series of the learning curve's plot: the
// series of its stage and spec (its label without the repetition).
void AddLearningRow(const std::string& stage, const calibrate::FittedTarget& f,
                    double lab_sd, CalibrationTables* t) {
  const calibrate::Target& target = f.target;
  const std::string series =
      fmt::format("stage {}: {} of {}", stage, target.spec.quantity, target.spec.part);
  auto it = std::find_if(t->learning_rows.begin(), t->learning_rows.end(),
                         [&](const auto& s) { return s.first == series; });
  if (it == t->learning_rows.end())
    it = t->learning_rows.insert(t->learning_rows.end(), {series, {}});
  it->second.push_back(DataRow()
                           .Integer(target.repetition)
                           .Number(target.lab.value)
                           .Number(1.96 * lab_sd)
                           .Number(f.fitted.value)
                           .Number(1.96 * Sd(f.fitted.variance)));
}

void AddTargets(const std::string& stage, const calibrate::CalibrationResult& r,
                CalibrationTables* t) {
  MarkdownTable md{{"target", "lab (se, n)", "virtual at start (se)",
                    "virtual at the fit (se)", "residual (sd)"}};
  for (const calibrate::FittedTarget& f : r.targets) {
    const double lab_sd = Sd(calibrate::LabVariance(f.target.lab, f.fitted));
    t->targets.AddRow({stage, f.target.label, f.target.unit, f.target.lab.value, lab_sd,
                       std::int64_t{f.target.lab.n}, f.start.value, Sd(f.start.variance),
                       f.fitted.value, Sd(f.fitted.variance), std::int64_t{f.fitted.n},
                       f.residual});
    md.AddRow(
        {fmt::format("{} ({})", f.target.label, f.target.unit),
         fmt::format("{} ({}{}, {})", Number(f.target.lab.value), Number(lab_sd),
                     f.target.lab.single_draw ? ": one draw" : "", f.target.lab.n),
         fmt::format("{} ({})", Number(f.start.value), Number(Sd(f.start.variance))),
         fmt::format("{} ({})", Number(f.fitted.value), Number(Sd(f.fitted.variance))),
         fmt::format("{:.2f}", f.residual)});
    // x, label, lab, lab half-width, start, start hw, fit, fit hw (95 %)
    if (f.target.repetition > 0) AddLearningRow(stage, f, lab_sd, t);
    t->plot_rows.push_back(DataRow()
                               .Integer(static_cast<std::int64_t>(t->plot_rows.size()))
                               .Label(f.target.label)
                               .Number(f.target.lab.value)
                               .Number(1.96 * lab_sd)
                               .Number(f.start.value)
                               .Number(1.96 * Sd(f.start.variance))
                               .Number(f.fitted.value)
                               .Number(1.96 * Sd(f.fitted.variance)));
  }
  t->markdown += "\n" + ToMarkdown(md);
}

// What the solver said, the search's steps and Ceres' full report folded.
std::string SolverText(const calibrate::CalibrationResult& r) {
  std::string md = fmt::format("\nSolver:\n\n```\n{}```\n", r.ceres_brief);
  const auto details = [&](const char* summary, const std::string& text) {
    if (!text.empty())
      md += fmt::format("\n<details><summary>{}</summary>\n\n```\n{}```\n\n</details>\n",
                        summary, text);
  };
  details("The bracketed search, step by step", r.search_log);
  details("Ceres' full report (last round)", r.ceres_full);
  return md;
}

constexpr const char* kProfileNote =
    "\nThe profile interval holds the values whose cost (1/2 the sum of the whitened "
    "squared residuals, on common random numbers) is within chi^2_1(0.95) / 2 = 1.92 "
    "of the estimate's: it needs no slope, so it holds where the cost is a step "
    "function and the standard error, from Ceres' slope at the estimate, does not; an "
    "end that reaches the parameter's bound is open there (docs/calibration.md).\n";
constexpr const char* kProfileRefitNote =
    "\nThe profile interval holds the values whose profile, the least cost (1/2 the sum "
    "of the whitened squared residuals, on common random numbers) with the parameter "
    "held there and the others re-fitted, is within chi^2_1(0.95) / 2 = 1.92 of the "
    "estimate's: unlike the standard error, from the curvature at the estimate, it "
    "follows a curved valley in which parameters trade against each other "
    "(docs/calibration.md, Profile intervals).\n";
constexpr const char* kRankDeficientNote =
    "\nThe covariance is rank deficient (the targets do not move within a "
    "central-difference step of the estimate, or a parameter they do not "
    "determine): no standard errors.\n";

// Points (value, rise) of a parameter's cost into `table` and, as a series
// of (position between the estimate and the ends of its valid range, rise),
// into `series`.
void AddCostPoints(const std::string& stage, const std::string& stage_label,
                   const calibrate::FittedParameter& p,
                   const std::vector<std::pair<double, double>>& points, Table* table,
                   std::vector<std::pair<std::string, std::vector<DataRow>>>* series) {
  if (points.empty()) return;
  std::vector<DataRow> rows;
  for (const auto& [value, rise] : points) {
    table->AddRow({stage, p.name, value, rise});
    const double span =
        value < p.estimate ? p.estimate - p.edge_lower : p.edge_upper - p.estimate;
    rows.push_back(
        DataRow().Number(span > 0 ? (value - p.estimate) / span : 0.0).Number(rise));
  }
  series->emplace_back(stage_label + p.name, std::move(rows));
}

// Each parameter's scan of the cost and its profile (a Levenberg-Marquardt
// stage's).
void AddScans(const std::string& stage, const calibrate::CalibrationResult& r,
              CalibrationTables* t) {
  const std::string label = r.stage.empty() ? "" : r.stage + ": ";
  for (const calibrate::FittedParameter& p : r.parameters) {
    AddCostPoints(stage, label, p, p.scan, &t->scan, &t->scan_rows);
    if (r.solver != "golden_section")
      AddCostPoints(stage, label, p, p.profile_points, &t->profile, &t->profile_rows);
  }
}

void AddStage(const calibrate::CalibrationResult& r,
              const calibrate::CalibrationDesign& d,
              const calibrate::CalibrationStage& spec, CalibrationTables* t) {
  const std::string stage = r.stage.empty() ? "1" : r.stage;
  t->markdown += StageHeading(r, d);
  AddParameters(stage, r, spec, t);
  if (r.solver == "golden_section") t->markdown += kProfileNote;
  if (r.solver != "golden_section" && d.intervals == "profile") {
    t->markdown += kProfileRefitNote;
    if (r.profile_least_rise < -0.1)
      t->markdown += fmt::format(
          "\n**A re-fit of the profile found a cost {:.3g} below the estimate's**: the "
          "fit stopped short of the minimum, and the profile intervals are measured "
          "from too high a cost (raise max_iterations).\n",
          -r.profile_least_rise);
  }
  if (!r.covariance_ok) t->markdown += kRankDeficientNote;
  AddTargets(stage, r, t);
  AddScans(stage, r, t);
  t->markdown += SolverText(r);
  for (std::size_t i = 0; i < r.parameters.size(); ++i)
    for (std::size_t j = 0; j < r.parameters.size(); ++j)
      t->covariance.AddRow(
          {stage, r.parameters[i].name, r.parameters[j].name,
           static_cast<double>(
               r.covariance(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j))),
           static_cast<double>(r.correlation(static_cast<Eigen::Index>(i),
                                             static_cast<Eigen::Index>(j)))});
  t->stages_json.push_back({{"stage", stage},
                            {"solver", r.solver},
                            {"converged", r.converged},
                            {"covariance_ok", r.covariance_ok},
                            {"jacobian_rank", r.rank.rank},
                            {"jacobian_condition", r.rank.condition},
                            {"refused_points", r.refused},
                            {"evaluations", r.evaluations},
                            {"rounds", r.rounds},
                            {"final_cost", r.final_cost}});
  // With profile intervals: the least rise a re-fit found (below 0, a cost
  // under the estimate's: the fit stopped short of its minimum).
  const bool profiled = std::any_of(r.parameters.begin(), r.parameters.end(),
                                    [](const auto& f) { return f.has_profile; });
  if (profiled && r.solver != "golden_section")
    t->stages_json.back()["profile_least_rise"] = r.profile_least_rise;
}

// Each target: the lab's value and the virtual one at the start and at the
// fit, side by side with their 95 % half-widths.
Figure TargetsFigure(const std::vector<DataRow>& rows) {
  Figure f;
  f.Data("d", rows)
      .Title("Lab against virtual, before and after the fit")
      .YLabel("value (the target unit: s for times, 1 for rates)")
      .CategoryRange(rows.size())
      .Set("grid y")
      .Set("key outside bottom center horizontal")
      .Draw({"$d", "($1-0.15):3:4:xtic(2)", "with yerrorbars pt 7", "lab"})
      .Draw({"''", "1:5:6", "with yerrorbars pt 6", "virtual at start"})
      .Draw({"''", "($1+0.15):7:8", "with yerrorbars pt 5", "virtual at the fit"});
  return f;
}

// The learning curve: each repetition's lab value against the virtual one at
// the fit (95 % intervals), per stage and target.
Figure LearningFigure(
    const std::vector<std::pair<std::string, std::vector<DataRow>>>& series) {
  Figure f;
  for (std::size_t k = 0; k < series.size(); ++k)
    f.Data(fmt::format("r{}", k), series[k].second);
  f.Title("Learning over repetitions: lab against virtual at the fit")
      .XLabel("repetition")
      .YLabel("value (the target unit: s for times, 1 for rates)")
      .Set("grid")
      .Set("key outside bottom center horizontal");
  for (std::size_t k = 0; k < series.size(); ++k) {
    const std::string data = fmt::format("$r{}", k);
    f.Draw({data, "($1-0.1):2:3", "with yerrorbars pt 7", "lab, " + series[k].first});
    f.Draw({data, "($1+0.1):4:5", "with yerrorbars pt 5",
            "virtual at the fit, " + series[k].first});
  }
  return f;
}

// The cost along each parameter alone, from its estimate (0) to the ends
// of its valid range (-1 and 1), against the 95 % profile threshold.
Figure ScanFigure(const std::vector<std::pair<std::string, std::vector<DataRow>>>& scans,
                  const std::string& title) {
  Figure f;
  for (std::size_t k = 0; k < scans.size(); ++k)
    f.Data(fmt::format("s{}", k), scans[k].second);
  // Drawn up to 10: what decides is whether a curve passes 1.92.
  f.Title(title)
      .XLabel("from the estimate (0) to the lower (-1) and upper (1) end of its range")
      .YLabel("rise of the cost (drawn up to 10)")
      .Set("yrange [0:10]")
      .Set("grid")
      .Set("key outside bottom center horizontal");
  for (std::size_t k = 0; k < scans.size(); ++k)
    f.Draw({fmt::format("$s{}", k), "1:2", "with linespoints pt 7", scans[k].first});
  f.Draw({fmt::format("{:.4f}", calibrate::ProfileRise()), "",
          "with lines dt 2 lc rgb 'black'",
          "chi^2_1(0.95) / 2: the 95 % profile threshold"});
  return f;
}

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
  int evaluations = 0;
  for (const calibrate::CalibrationResult& r : stages) evaluations += r.evaluations;
  CalibrationTables t;
  t.markdown = Intro(file, lab, stages, evaluations);
  for (std::size_t k = 0; k < stages.size(); ++k)
    AddStage(stages[k], file.Input<calibrate::CalibrationDesign>(),
             file.Input<calibrate::CalibrationDesign>().stages[k], &t);
  t.markdown += fmt::format(
      "\nThe fitted values are in `{}`, a parameter-override file: "
      "`vahf run EXPERIMENT --overrides {}` runs any experiment with them.\n\n",
      kOverridesFile, kOverridesFile);
  Section out;
  out.tables.emplace_back("calibrate_parameters.csv", std::move(t.params));
  out.tables.emplace_back("calibrate_targets.csv", std::move(t.targets));
  out.tables.emplace_back("calibrate_covariance.csv", std::move(t.covariance));
  const bool scanned = !t.scan_rows.empty();
  if (scanned) out.tables.emplace_back("calibrate_scan.csv", std::move(t.scan));
  const bool profiled = !t.profile_rows.empty();
  if (profiled) out.tables.emplace_back("calibrate_profile.csv", std::move(t.profile));
  out.files.emplace_back(kOverridesFile, OverridesJson(file, stages).dump(1) + "\n");
  out.summary = {{"parameters", t.params_json},
                 {"stages", t.stages_json},
                 {"evaluations", evaluations},
                 {"claims", nlohmann::json::array()}};
  out.markdown = t.markdown;
  out.plots.push_back(
      {"plots/calibrate_targets.png",
       "Each target: the lab's value and the virtual one at the start and "
       "at the fit (95 % intervals)",
       GnuplotScript(TargetsFigure(t.plot_rows))});
  if (!t.learning_rows.empty())
    out.plots.push_back(
        {"plots/calibrate_learning.png",
         "Learning over repetitions: each repetition's lab value and the virtual one "
         "at the fitted parameters (95 % intervals)",
         GnuplotScript(LearningFigure(t.learning_rows))});
  if (scanned)
    out.plots.push_back(
        {"plots/calibrate_scan.png",
         "The cost along each parameter alone, from its estimate to the ends of its "
         "valid range: below the dashed line at both ends, the targets do not "
         "determine it there (docs/calibration.md, Identifiability)",
         GnuplotScript(ScanFigure(
             t.scan_rows, "The cost along each parameter, the others at the estimate"))});
  if (profiled)
    out.plots.push_back(
        {"plots/calibrate_profile.png",
         "The profile of the cost along each parameter, the others re-fitted at each "
         "point: where it crosses the dashed line are the ends of the 95 % profile "
         "interval (docs/calibration.md, Profile intervals)",
         GnuplotScript(ScanFigure(t.profile_rows,
                                  "The profile of the cost along each parameter, the "
                                  "others re-fitted"))});
  return out;
}

}  // namespace vahf::report
