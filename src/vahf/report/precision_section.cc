// Error against run time (docs/experiments.md, "precision"): each setting of
// each scene against the reference on the same cycles, the Monte Carlo noise
// of the experiment that will use it, and the cheapest setting under that
// noise. The statistics are report/precision.h's; this file lays them out as
// tables, summary.json, measured.json, report.md and work-precision diagrams.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include "vahf/experiment/precision_design.h"
#include "vahf/report/figure.h"
#include "vahf/report/markdown.h"
#include "vahf/report/precision.h"
#include "vahf/report/section.h"
#include "vahf/stats/distribution.h"

namespace vahf::report {
namespace {

const char* const kRule =
    "A setting meets the rule for a part when at least 2 cycles completed the part under "
    "it and under the reference, and, with the Monte Carlo noise = the reference's "
    "completion-time standard deviation / sqrt(noise_trials): the larger end (in "
    "absolute "
    "value) of the 95 % t interval of the paired mean difference of completion time is "
    "below the noise; the KS distance as a shift (the smallest shift of the reference's "
    "completion times that puts them as far from themselves) is below the noise; the "
    "two-sample KS test does not tell the setting's times from the reference's at the 5 "
    "% "
    "level; and the outcome (status, or not reaching the part) differs from the "
    "reference's in fewer "
    "than 5 % of the cycles. The recommended setting of a scene is the cheapest by "
    "median "
    "wall time per cycle among those meeting the rule for every part; the reference "
    "meets "
    "it by definition.";

double Or(const std::optional<double>& x) { return x.value_or(NAN); }

nlohmann::json Json(const std::optional<double>& x) {
  return x ? nlohmann::json(*x) : nlohmann::json(nullptr);
}

std::string Ms(const std::optional<double>& x) {
  return x ? fmt::format("{:.3g}", *x * 1e3) : "-";
}

std::string Seconds(const std::optional<double>& x) {
  return x ? fmt::format("{:.3g}", *x) : "-";
}

std::string Count(const std::optional<double>& x) {
  return x ? fmt::format("{:.0f}", *x) : "-";
}

nlohmann::json Overrides(const experiment::PrecisionSetting& s) {
  nlohmann::json o = nlohmann::json::object();
  for (const auto& [name, value] : s.overrides) o[name] = value;
  return o;
}

// One scene's outcomes: [setting][part][cycle], setting 0 the reference.
struct SceneData {
  const experiment::PrecisionScene* scene = nullptr;
  std::vector<const experiment::PrecisionSetting*> settings;  // reference first
  std::vector<std::string> parts;
  std::size_t cycles = 0;
  std::vector<std::vector<std::vector<PartOutcome>>> outcomes;
  std::vector<std::vector<double>> cycle_wall;           // [setting][cycle], s
  std::vector<std::vector<PartComparison>> comparisons;  // [setting][part]
  std::vector<std::vector<WallSummary>> wall;            // [setting][part]
};

std::vector<SceneData> Collect(const experiment::ExperimentRun& run) {
  const experiment::PrecisionDesign& d = run.file->Input<experiment::PrecisionDesign>();
  const experiment::DesignRun& design = run.run;
  std::vector<std::vector<const experiment::CycleRecord*>> by_condition(
      design.conditions.size());
  for (const experiment::CycleRecord& r : design.records)
    by_condition[r.condition].push_back(&r);  // in cycle order
  std::vector<SceneData> out;
  for (std::size_t s = 0; s < d.scenes.size(); ++s) {
    SceneData sd;
    sd.scene = &d.scenes[s];
    sd.settings.push_back(&d.reference);
    for (const experiment::PrecisionSetting& x : d.settings) sd.settings.push_back(&x);
    const scene::Scene& scene = sd.scene->scene;
    for (int index : scene.sequence) sd.parts.push_back(scene.parts[index].name);
    sd.cycles = by_condition[experiment::PrecisionConditionIndex(d, s, 0)].size();
    for (std::size_t k = 0; k < sd.settings.size(); ++k) {
      const auto& records = by_condition[experiment::PrecisionConditionIndex(d, s, k)];
      std::vector<std::vector<PartOutcome>> parts(sd.parts.size());
      std::vector<double> walls;
      for (const experiment::CycleRecord* r : records) {
        double wall = 0;
        for (std::size_t p = 0; p < sd.parts.size(); ++p) {
          PartOutcome o;
          if (p < r->result.parts.size()) {
            const sim::TrialResult& t = r->result.parts[p].trial;
            o.reached = true;
            o.status = t.status;
            o.completion_time = t.completion_time;
            o.wall_seconds = t.wall_seconds;
            o.steps = t.counters.steps_taken;
            o.realizations = t.counters.realizations;
            wall += t.wall_seconds;
          }
          parts[p].push_back(o);
        }
        walls.push_back(wall);
      }
      sd.outcomes.push_back(std::move(parts));
      sd.cycle_wall.push_back(std::move(walls));
    }
    for (std::size_t k = 0; k < sd.settings.size(); ++k) {
      std::vector<PartComparison> c;
      std::vector<WallSummary> w;
      for (std::size_t p = 0; p < sd.parts.size(); ++p) {
        c.push_back(ComparePart(sd.outcomes[k][p], sd.outcomes[0][p], d.noise_trials));
        w.push_back(SummarizeWall(sd.outcomes[k][p]));
      }
      sd.comparisons.push_back(std::move(c));
      sd.wall.push_back(std::move(w));
    }
    out.push_back(std::move(sd));
  }
  return out;
}

// Every part's failures of a setting, each prefixed by the part's name when
// the scene has several.
std::string SettingFailures(const SceneData& sd, std::size_t k) {
  std::string out;
  for (std::size_t p = 0; p < sd.parts.size(); ++p) {
    const std::string& f = sd.comparisons[k][p].failures;
    if (f.empty()) continue;
    out += (out.empty() ? "" : "; ") +
           (sd.parts.size() > 1 ? sd.parts[p] + ": " : std::string()) + f;
  }
  return out;
}

nlohmann::json ComparisonJson(const PartComparison& c) {
  return {
      {"cycles", c.cycles},
      {"completed", c.completed},
      {"paired", c.paired},
      {"mean_difference_s", Json(c.difference.mean)},
      {"ci_lower_s", c.difference.ci ? nlohmann::json(c.difference.ci->lower) : nullptr},
      {"ci_upper_s", c.difference.ci ? nlohmann::json(c.difference.ci->upper) : nullptr},
      {"difference_bound_s", Json(c.difference_bound)},
      {"mean_abs_difference_s", Json(c.mean_abs_difference)},
      {"ks_distance", c.ks ? nlohmann::json(c.ks->distance) : nullptr},
      {"ks_p_value", c.ks ? nlohmann::json(c.ks->p_value) : nullptr},
      {"ks_shift_s", Json(c.ks_shift)},
      {"ks_noise_distance", Json(c.ks_noise_distance)},
      {"p10_s", Json(c.p10)},
      {"p90_s", Json(c.p90)},
      {"reference_p10_s", Json(c.reference_p10)},
      {"reference_p90_s", Json(c.reference_p90)},
      {"outcome_differences", c.outcome_differences},
      {"outcome_share", c.outcome_share},
      {"reference_completed", c.reference_completed},
      {"reference_sd_s", Json(c.reference_sd)},
      {"noise_s", Json(c.noise)},
      {"steps_median", Json(c.steps_median)},
      {"realizations_median", Json(c.realizations_median)},
      {"meets_rule", c.meets_rule()},
      {"failures", c.failures}};
}

// A work-precision diagram of one error measure for one scene: a panel per
// part, error against median wall per trial on log-log axes, a line per
// integrator through its accuracy-only settings, other settings as points,
// and the threshold of the rule as a horizontal line. Zeros, which a log axis
// cannot show, are drawn on the bottom edge.
struct Measure {
  const char* file;  // plot file stem
  const char* title;
  const char* ylabel;
  std::optional<double> (*value)(const PartComparison&);
  std::optional<double> (*bound)(const PartComparison&);  // error-bar top, or none
  std::optional<double> (*threshold)(const PartComparison& reference);
  const char* threshold_title;
};

std::optional<double> AbsMeanDifference(const PartComparison& c) {
  if (!c.difference.mean) return std::nullopt;
  return std::fabs(*c.difference.mean);
}
std::optional<double> DifferenceBound(const PartComparison& c) {
  return c.difference_bound;
}
std::optional<double> KsDistance(const PartComparison& c) {
  if (!c.ks) return std::nullopt;
  return c.ks->distance;
}
std::optional<double> OutcomeShare(const PartComparison& c) { return c.outcome_share; }
std::optional<double> Noise(const PartComparison& c) { return c.noise; }
// The KS distance a shift of the reference's times by the noise gives.
std::optional<double> KsNoise(const PartComparison& c) { return c.ks_noise_distance; }
std::optional<double> OutcomeLimit(const PartComparison&) { return kMaxOutcomeShare; }
std::optional<double> None(const PartComparison&) { return std::nullopt; }

const Measure kMeasures[] = {
    {"difference", "|paired mean difference| of completion time", "|mean difference| (s)",
     AbsMeanDifference, DifferenceBound, Noise, "Monte Carlo noise"},
    {"ks", "two-sample KS distance of completion times", "KS distance", KsDistance, None,
     KsNoise, "KS distance of the reference shifted by the noise"},
    {"outcomes", "share of cycles whose outcome differs", "share of cycles", OutcomeShare,
     None, OutcomeLimit, "5 % (the rule)"},
};

// The settings' points of one part under a measure: median wall per trial
// against the error (and its bar's top), and the floor that stands in for
// zero on the log axis: a tenth of the smallest positive value or threshold.
struct PanelPoints {
  struct Point {
    std::size_t k;
    double x, y, top;
  };
  std::vector<Point> points;
  std::optional<double> threshold;
  double floor = 1e-6;
};

PanelPoints PointsOf(const SceneData& sd, const Measure& m, std::size_t p) {
  PanelPoints out;
  double smallest = INFINITY;
  for (std::size_t k = 1; k < sd.settings.size(); ++k) {
    const PartComparison& c = sd.comparisons[k][p];
    const std::optional<double> y = m.value(c);
    const std::optional<double> x = sd.wall[k][p].median;
    if (!y || !x || !(*x > 0)) continue;
    const double top = m.bound(c).value_or(*y);
    out.points.push_back({k, *x, *y, top});
    for (double v : {*y, top})
      if (v > 0) smallest = std::min(smallest, v);
  }
  out.threshold = m.threshold(sd.comparisons[0][p]);
  if (out.threshold && *out.threshold > 0) smallest = std::min(smallest, *out.threshold);
  if (std::isfinite(smallest)) out.floor = smallest / 10;
  return out;
}

// One panel of a work-precision diagram: a data block and series per setting
// that is not accuracy-only (points) and per integrator through its
// accuracy-only settings (a line, loosest accuracy first), the threshold as
// a dashed line; a note when no setting has the measure.
void AddPanel(const SceneData& sd, const Measure& m, std::size_t p, Figure* f) {
  const PanelPoints pp = PointsOf(sd, m, p);
  const bool bars = m.bound != None;  // from the value up to its bound
  const auto clamp = [&](double v) { return v > 0 ? v : pp.floor; };
  std::vector<Series> series;
  const auto add = [&](const std::string& block, const std::vector<DataRow>& rows,
                       const std::string& title, bool line) {
    f->Data(block, rows);
    series.push_back(
        {"$" + block, bars ? "1:2:2:3" : "1:2",
         line ? (bars ? "with yerrorlines pt 7" : "with linespoints pt 7")
              : (bars ? "with yerrorbars pt 6 ps 1.5" : "with points pt 6 ps 1.5"),
         title});
  };
  std::map<std::string, std::vector<std::pair<double, DataRow>>> by_integrator;
  for (const PanelPoints::Point& pt : pp.points) {
    const DataRow row = DataRow().Number(pt.x).Number(clamp(pt.y)).Number(clamp(pt.top));
    const experiment::PrecisionSetting& s = *sd.settings[pt.k];
    if (!s.AccuracyOnly()) {
      add(fmt::format("p{}s{}", p, pt.k), {row}, s.label, false);
      continue;
    }
    const scene::Scene& scene = sd.scene->settings[pt.k - 1];
    by_integrator[scene.params.simulation.integrator].emplace_back(
        -scene.params.simulation.accuracy, row);
  }
  std::size_t line = 0;
  for (auto& [integrator, rows] : by_integrator) {
    // Loosest accuracy first (equal accuracies by their rows' text).
    std::sort(rows.begin(), rows.end(), [](const auto& a, const auto& b) {
      return std::make_pair(a.first, a.second.Text()) <
             std::make_pair(b.first, b.second.Text());
    });
    std::vector<DataRow> block;
    for (const auto& [accuracy, row] : rows) block.push_back(row);
    add(fmt::format("p{}l{}", p, line++), block, integrator, true);
  }
  if (!series.empty() && pp.threshold && *pp.threshold > 0)
    series.push_back({fmt::format("{}", *pp.threshold), "",
                      "with lines dt 2 lc rgb 'black'", m.threshold_title});
  f->Title(sd.parts[p]).Set(fmt::format("yrange [{}:*]", pp.floor));
  if (series.empty()) {
    f->Set("label 1 'no setting has this measure' at graph 0.5, 0.5 center")
        .Draw({"[1:10] [1:10] 2", "", "lc rgb 'white'", std::nullopt})
        .Unset("label 1");
  }
  for (Series& s : series) f->Draw(std::move(s));
}

// A work-precision diagram of one error measure for one scene: a panel per
// part, error against median wall per trial on log-log axes (AddPanel). Zeros,
// which a log axis cannot show, are drawn on the bottom edge.
Plot WorkPrecisionPlot(const SceneData& sd, const Measure& m) {
  const std::size_t np = sd.parts.size();
  const std::string title = fmt::format("{}: {}", sd.scene->scene.name, m.title);
  Figure f;
  f.Terminal(fmt::format("pngcairo size {},500 noenhanced",
                         std::max<std::size_t>(800, 100 + 500 * np)));
  f.Set(fmt::format("multiplot layout 1,{} title {}", np, GnuplotString(title)))
      .Set("logscale xy")
      .Set("format xy '%g'")
      .Set("grid")
      .Set("key below font ',9'")
      .XLabel("median wall per trial (s)")
      .YLabel(m.ylabel);
  for (std::size_t p = 0; p < np; ++p) AddPanel(sd, m, p, &f);
  f.Unset("multiplot");
  const bool bars = m.bound != None;
  return {
      fmt::format("plots/precision_{}_{}.png", sd.scene->scene.name, m.file),
      fmt::format("{} against median wall time per trial ({} cycles per setting; the "
                  "reference itself is not drawn; a zero is drawn on the bottom edge{})",
                  title, sd.cycles,
                  bars ? "; the error bars reach the larger end of the difference's 95 % "
                         "interval"
                       : ""),
      GnuplotScript(f)};
}

// The trials' tables (deterministic and measured) and the settings' table.
struct PrecisionTables {
  Table trials{{"scene", "setting", "cycle", "position", "part", "status",
                "completion_time_s", "steps_taken", "realizations"}};
  Table wall{{"scene", "setting", "cycle", "position", "part", "status", "wall_s"}};
  Table settings{{"scene",
                  "setting",
                  "reference",
                  "position",
                  "part",
                  "cycles",
                  "completed",
                  "paired",
                  "mean_difference_s",
                  "ci_lower_s",
                  "ci_upper_s",
                  "difference_bound_s",
                  "mean_abs_difference_s",
                  "ks_distance",
                  "ks_p_value",
                  "ks_shift_s",
                  "ks_noise_distance",
                  "p10_s",
                  "p90_s",
                  "reference_p10_s",
                  "reference_p90_s",
                  "outcome_differences",
                  "outcome_share",
                  "reference_sd_s",
                  "noise_s",
                  "steps_median",
                  "realizations_median",
                  "meets_rule",
                  "failures"}};
};

void AddTrialRows(const SceneData& sd, PrecisionTables* t) {
  const std::string& name = sd.scene->scene.name;
  for (std::size_t k = 0; k < sd.settings.size(); ++k)
    for (std::size_t j = 0; j < sd.cycles; ++j)
      for (std::size_t p = 0; p < sd.parts.size(); ++p) {
        const PartOutcome& o = sd.outcomes[k][p][j];
        if (!o.reached) continue;
        const auto cycle = static_cast<std::int64_t>(j);
        const auto position = static_cast<std::int64_t>(p);
        t->trials.AddRow({name, sd.settings[k]->label, cycle, position, sd.parts[p],
                          o.StatusText(), o.completed() ? o.completion_time : NAN,
                          o.steps, o.realizations});
        t->wall.AddRow({name, sd.settings[k]->label, cycle, position, sd.parts[p],
                        o.StatusText(), o.wall_seconds});
      }
}

std::vector<Table::Cell> SettingCells(const SceneData& sd, std::size_t k, std::size_t p) {
  const PartComparison& c = sd.comparisons[k][p];
  return {sd.scene->scene.name,
          sd.settings[k]->label,
          std::int64_t{k == 0 ? 1 : 0},
          static_cast<std::int64_t>(p),
          sd.parts[p],
          static_cast<std::int64_t>(c.cycles),
          static_cast<std::int64_t>(c.completed),
          static_cast<std::int64_t>(c.paired),
          Or(c.difference.mean),
          c.difference.ci ? c.difference.ci->lower : NAN,
          c.difference.ci ? c.difference.ci->upper : NAN,
          Or(c.difference_bound),
          Or(c.mean_abs_difference),
          c.ks ? c.ks->distance : NAN,
          c.ks ? c.ks->p_value : NAN,
          Or(c.ks_shift),
          Or(c.ks_noise_distance),
          Or(c.p10),
          Or(c.p90),
          Or(c.reference_p10),
          Or(c.reference_p90),
          static_cast<std::int64_t>(c.outcome_differences),
          c.outcome_share,
          Or(c.reference_sd),
          Or(c.noise),
          Or(c.steps_median),
          Or(c.realizations_median),
          std::int64_t{c.meets_rule() ? 1 : 0},
          c.failures};
}

nlohmann::json WallJson(const std::string& part, const WallSummary& w) {
  return {{"part", part},
          {"trials", w.n},
          {"wall_median_s", Json(w.median)},
          {"wall_p10_s", Json(w.p10)},
          {"wall_p90_s", Json(w.p90)}};
}

// One scene's settings: their rows, summary.json's and measured.json's
// entries, and each as a candidate for the recommendation.
struct SceneSettings {
  nlohmann::json summary = nlohmann::json::array();
  nlohmann::json measured = nlohmann::json::array();
  std::vector<Candidate> candidates;
};

SceneSettings DescribeSettings(const SceneData& sd, PrecisionTables* t) {
  SceneSettings out;
  for (std::size_t k = 0; k < sd.settings.size(); ++k) {
    const experiment::PrecisionSetting& s = *sd.settings[k];
    nlohmann::json parts = nlohmann::json::array();
    nlohmann::json walls = nlohmann::json::array();
    for (std::size_t p = 0; p < sd.parts.size(); ++p) {
      t->settings.AddRow(SettingCells(sd, k, p));
      nlohmann::json pj = ComparisonJson(sd.comparisons[k][p]);
      pj["part"] = sd.parts[p];
      parts.push_back(pj);
      walls.push_back(WallJson(sd.parts[p], sd.wall[k][p]));
    }
    const std::string failures = SettingFailures(sd, k);
    out.summary.push_back({{"setting", s.label},
                           {"reference", k == 0},
                           {"overrides", Overrides(s)},
                           {"meets_rule", failures.empty()},
                           {"failures", failures},
                           {"parts", parts}});
    const double cost = stats::Quantile(sd.cycle_wall[k], 0.5);
    out.measured.push_back(
        {{"setting", s.label}, {"wall_per_cycle_median_s", cost}, {"parts", walls}});
    out.candidates.push_back({s.label, cost, k == 0, failures});
  }
  return out;
}

// measured.json's entry for the recommended setting: its errors per part.
nlohmann::json RecommendedJson(const SceneData& sd, const Recommendation& rec,
                               const std::vector<Candidate>& candidates) {
  const experiment::PrecisionSetting& chosen = *sd.settings[rec.index];
  nlohmann::json errors = nlohmann::json::object();
  for (std::size_t p = 0; p < sd.parts.size(); ++p) {
    const PartComparison& c = sd.comparisons[rec.index][p];
    errors[sd.parts[p]] = {
        {"difference_bound_s", Json(c.difference_bound)},
        {"ks_distance", c.ks ? nlohmann::json(c.ks->distance) : nullptr},
        {"ks_shift_s", Json(c.ks_shift)},
        {"outcome_share", c.outcome_share},
        {"noise_s", Json(c.noise)}};
  }
  return {{"setting", chosen.label},
          {"overrides", Overrides(chosen)},
          {"wall_per_cycle_median_s", candidates[rec.index].cost},
          {"errors", errors},
          {"why", rec.why}};
}

// A setting against the reference for one part, as report.md shows it.
std::vector<std::string> SettingMarkdown(const SceneData& sd, std::size_t k,
                                         std::size_t p) {
  const PartComparison& c = sd.comparisons[k][p];
  const WallSummary& w = sd.wall[k][p];
  const std::string ci =
      c.difference.ci ? fmt::format(" [{:.3g}, {:.3g}]", c.difference.ci->lower * 1e3,
                                    c.difference.ci->upper * 1e3)
                      : "";
  return {k == 0 ? "**" + sd.settings[k]->label + "**" : sd.settings[k]->label,
          sd.parts[p],
          fmt::format("{} [{}, {}]", Seconds(w.median), Seconds(w.p10), Seconds(w.p90)),
          Count(c.steps_median),
          Count(c.realizations_median),
          Ms(c.difference.mean) + ci,
          Ms(c.mean_abs_difference),
          c.ks ? fmt::format("{:.3f} ({:.2g})", c.ks->distance, c.ks->p_value) : "-",
          Ms(c.ks_shift),
          fmt::format("{}-{}", Seconds(c.p10), Seconds(c.p90)),
          fmt::format("{}-{}", Seconds(c.reference_p10), Seconds(c.reference_p90)),
          fmt::format("{}/{}", c.outcome_differences, c.cycles),
          k == 0           ? "reference"
          : c.meets_rule() ? "meets"
                           : "no: " + c.failures};
}

// A scene's subsection: the noise, every setting against the reference, the
// recommendation.
std::string SceneMarkdown(const SceneData& sd, const Recommendation& rec) {
  const std::string& name = sd.scene->scene.name;
  std::string md =
      fmt::format("### {} (`{}`), {} cycles per setting\n\nMonte Carlo noise:", name,
                  sd.scene->path, sd.cycles);
  for (std::size_t p = 0; p < sd.parts.size(); ++p) {
    const PartComparison& ref = sd.comparisons[0][p];
    md += fmt::format("{} {} {} ms (sd {} ms over {} completions)", p ? ";" : "",
                      sd.parts[p], Ms(ref.noise), Ms(ref.reference_sd),
                      ref.reference_completed);
  }
  MarkdownTable table{{"setting", "part", "wall per trial (s), median [p10, p90]",
                       "steps", "realizations", "mean difference (ms) [95 % CI]",
                       "mean abs. difference (ms)", "KS distance (p)",
                       "KS as a shift (ms)", "p10-p90 (s)", "reference p10-p90 (s)",
                       "outcome differs", "rule"}};
  for (std::size_t k = 0; k < sd.settings.size(); ++k)
    for (std::size_t p = 0; p < sd.parts.size(); ++p)
      table.AddRow(SettingMarkdown(sd, k, p));
  const experiment::PrecisionSetting& chosen = *sd.settings[rec.index];
  return md + ".\n\n" + ToMarkdown(table) +
         fmt::format("\n**Recommended for {}: {}** ({}). {}.\n\n", name, chosen.label,
                     Overrides(chosen).dump(), rec.why);
}

std::string PrecisionIntro(const experiment::PrecisionDesign& d) {
  return fmt::format(
      "## Error against run time (precision)\n\n"
      "Each setting runs the same cycles as the reference ({}), on common random "
      "numbers, and is compared part by part with it over the cycles in which both "
      "completed the part. The Monte Carlo noise is that of an experiment of {} cycles "
      "per condition (`noise_trials`). {}\n\n"
      "Wall seconds per trial are measured on this machine with the run's threads "
      "(several trials run at once and share the cores, the memory and the cache), so "
      "they rank the settings rather than time them; they and the recommendation are in "
      "`measured.json` and `precision_wall.csv`, outside the results digest.\n\n",
      d.reference.label.substr(d.reference.label.find(':') + 2), d.noise_trials, kRule);
}

}  // namespace

Section PrecisionSection(const experiment::ExperimentRun& run) {
  const experiment::PrecisionDesign& d = run.file->Input<experiment::PrecisionDesign>();
  PrecisionTables t;
  nlohmann::json summary_scenes = nlohmann::json::array();
  nlohmann::json measured_scenes = nlohmann::json::array();
  nlohmann::json recommended = nlohmann::json::object();
  Section out;
  out.markdown = PrecisionIntro(d);
  for (const SceneData& sd : Collect(run)) {
    const std::string& name = sd.scene->scene.name;
    AddTrialRows(sd, &t);
    const SceneSettings settings = DescribeSettings(sd, &t);
    const Recommendation rec = Recommend(settings.candidates);
    recommended[name] = RecommendedJson(sd, rec, settings.candidates);
    summary_scenes.push_back({{"scene", name},
                              {"file", sd.scene->path},
                              {"cycles", sd.cycles},
                              {"parts", sd.parts},
                              {"settings", settings.summary}});
    measured_scenes.push_back({{"scene", name}, {"settings", settings.measured}});
    out.markdown += SceneMarkdown(sd, rec);
    for (const Measure& m : kMeasures) out.plots.push_back(WorkPrecisionPlot(sd, m));
  }
  out.tables.emplace_back("precision_trials.csv", std::move(t.trials));
  out.tables.emplace_back("precision_settings.csv", std::move(t.settings));
  out.measured_tables.emplace_back("precision_wall.csv", std::move(t.wall));
  out.summary = {{"claims", nlohmann::json::array()},
                 {"noise_trials", d.noise_trials},
                 {"max_outcome_share", kMaxOutcomeShare},
                 {"rule", kRule},
                 {"scenes", summary_scenes}};
  out.measured = {
      {"note",
       "wall seconds per trial, measured on this machine with the run's threads "
       "(manifest.json: threads); the recommendation ranks settings by them"},
      {"scenes", measured_scenes},
      {"recommended", recommended}};
  return out;
}

}  // namespace vahf::report
