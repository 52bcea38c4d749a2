// Paper Sec. 5.2 (Figs. 11-12): assembly time of the cylinder per operator and
// of each subassembly, the male-female comparison, and time against part mass.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "vahf/report/figure.h"
#include "vahf/report/markdown.h"
#include "vahf/report/section.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

// The completion times of a design: of each cycle per operator and per sex,
// of each part per sex and pooled.
struct AssemblyTimes {
  std::vector<std::vector<double>> by_operator;
  std::vector<int> attempted;
  std::map<std::string, std::vector<double>> by_sex;
  // Per sex, cycle -> (sum, count) of completed cycle times: cycle j of every
  // operator runs on the same streams, so the sexes' means of cycle j pair.
  std::map<std::string, std::map<std::uint64_t, std::pair<double, int>>> sex_cycle;
  std::map<std::string, std::vector<std::vector<double>>> part_by_sex;
  std::vector<std::vector<double>> part_all;
  // Each cycle's part times (NaN: the part did not complete): a cycle's parts
  // are a pair for the part against part test.
  std::vector<std::vector<double>> cycle_parts;
};

void AddPartTimes(const experiment::CycleRecord& r, const std::string& sex,
                  AssemblyTimes* t) {
  const std::size_t n_parts = t->part_all.size();
  t->cycle_parts.emplace_back(n_parts, NAN);
  auto& parts = t->part_by_sex[sex];
  parts.resize(n_parts);
  for (std::size_t p = 0; p < r.result.parts.size(); ++p) {
    const sim::TrialResult& trial = r.result.parts[p].trial;
    if (trial.status != sim::Status::kCompleted) continue;
    parts[p].push_back(trial.completion_time);
    t->part_all[p].push_back(trial.completion_time);
    t->cycle_parts.back()[p] = trial.completion_time;
  }
}

AssemblyTimes CollectTimes(const experiment::DesignRun& d, std::size_t n_parts) {
  AssemblyTimes t;
  t.by_operator.resize(d.conditions.size());
  t.attempted.assign(d.conditions.size(), 0);
  t.part_all.resize(n_parts);
  for (const experiment::CycleRecord& r : d.records) {
    const std::string& sex = d.conditions[r.condition].group;
    ++t.attempted[r.condition];
    AddPartTimes(r, sex, &t);
    if (!r.result.completed) continue;
    t.by_operator[r.condition].push_back(r.result.time);
    t.by_sex[sex].push_back(r.result.time);
    auto& [sum, count] = t.sex_cycle[sex][r.cycle];
    sum += r.result.time;
    ++count;
  }
  return t;
}

double Lower(const stats::Summary& s) { return s.ci ? s.ci->lower : NAN; }
double Upper(const stats::Summary& s) { return s.ci ? s.ci->upper : NAN; }

// Table, Markdown and Fig. 11 of the cycle time per operator.
void DescribeOperators(const experiment::DesignRun& d, const AssemblyTimes& times,
                       Section* out) {
  Table table({"operator", "sex", "height_m", "arm_length_m", "cycles", "completed",
               "mean_time_s", "sd_s", "ci_lower_s", "ci_upper_s"});
  MarkdownTable md{{"operator", "sex", "height (m)", "arm (m)", "completed", "time (s)"}};
  std::vector<DataRow> fig;
  for (std::size_t c = 0; c < d.conditions.size(); ++c) {
    const experiment::Condition& cond = d.conditions[c];
    const auto& op = cond.scene->op;
    const stats::Summary s = stats::Summarize(times.by_operator[c]);
    table.AddRow({cond.name, cond.group, op.height, op.arm_length,
                  std::int64_t{times.attempted[c]}, static_cast<std::int64_t>(s.n),
                  s.mean.value_or(NAN), s.sd.value_or(NAN), Lower(s), Upper(s)});
    md.AddRow({cond.name, cond.group, fmt::format("{:.3f}", op.height),
               fmt::format("{:.3f}", op.arm_length),
               fmt::format("{}/{}", s.n, times.attempted[c]), MeanCi(s)});
    if (s.mean)
      fig.push_back(DataRow()
                        .Integer(static_cast<std::int64_t>(c))
                        .Label(cond.name)
                        .MeanAndInterval(s));
  }
  out->tables.emplace_back("assembly_time_operators.csv", std::move(table));
  out->markdown +=
      "## Assembly time per operator (Sec. 5.2, Figs. 11-12)\n\n"
      "Virtual time of the whole cylinder (completed cycles), mean and 95 % t "
      "interval.\n\n" +
      ToMarkdown(md);
  Figure f;
  f.Data("d", fig)
      .Title("Assembly time of the hydraulic cylinder per operator")
      .YLabel("time (s)")
      .CategoryRange(d.conditions.size())
      .Set("yrange [0:*]")
      .Set("style fill solid 0.4")
      .Set("boxwidth 0.6")
      .Set("grid y")
      .Draw({"$d", "1:3:xtic(2)", "with boxes", std::nullopt})
      .Draw({"''", "1:3:4:5", "with yerrorbars pt 7 lc black", std::nullopt});
  out->plots.push_back(
      {"plots/assembly_time_operators.png",
       "Fig. 11: virtual assembly time of the cylinder per operator (mean, 95 % "
       "interval)",
       GnuplotScript(f)});
}

// Table, Markdown and Fig. 12 of each subassembly's time against its mass.
void DescribeParts(const scene::Scene& scene, const AssemblyTimes& times, Section* out) {
  Table table({"position", "part", "mass_kg", "sex", "n", "mean_time_s", "ci_lower_s",
               "ci_upper_s"});
  MarkdownTable md{{"part", "mass (kg)", "all", "male", "female"}};
  std::vector<DataRow> fig;
  for (std::size_t p = 0; p < times.part_all.size(); ++p) {
    const scene::Part& part = scene.parts[scene.sequence[p]];
    std::vector<std::string> cells = {part.name, fmt::format("{:.3f}", part.mass),
                                      MeanCi(stats::Summarize(times.part_all[p]))};
    DataRow row = DataRow().Integer(static_cast<std::int64_t>(p)).Label(part.name);
    for (const char* sex : {"male", "female"}) {
      const auto it = times.part_by_sex.find(sex);
      const stats::Summary s = stats::Summarize(
          it == times.part_by_sex.end() ? std::vector<double>{} : it->second[p]);
      table.AddRow({static_cast<std::int64_t>(p), part.name, part.mass, std::string(sex),
                    static_cast<std::int64_t>(s.n), s.mean.value_or(NAN), Lower(s),
                    Upper(s)});
      cells.push_back(MeanCi(s));
      row.MeanAndInterval(s);
    }
    md.AddRow(std::move(cells));
    fig.push_back(row);
  }
  out->tables.emplace_back("assembly_time_parts.csv", std::move(table));
  out->markdown +=
      "\nSubassembly time (completed part trials), mean and 95 % interval, by sex:\n\n" +
      ToMarkdown(md);
  Figure f;
  f.Data("d", fig)
      .Title("Subassembly time (heaviest part first; mean, 95 % interval)")
      .YLabel("time (s)")
      .Set("yrange [0:*]")
      .Set("style data histograms")
      .Set("style histogram errorbars gap 1 lw 1")
      .Set("style fill solid 0.5")
      .Set("grid y")
      .Draw({"$d", "3:4:5:xtic(2)", "", "male"})
      .Draw({"''", "6:7:8", "", "female"});
  out->plots.push_back(
      {"plots/assembly_time_parts.png",
       "Fig. 12: virtual time of each subassembly, male and female operators",
       GnuplotScript(f)});
}

// Claim: the male operators are faster, paired by cycle over the sexes' means.
nlohmann::json SexClaim(const AssemblyTimes& times, nlohmann::json* tests) {
  const char* claim =
      "the male operators assemble the cylinder faster than the female ones";
  const char* test =
      "paired t test of the male and female operators' mean time of each cycle, "
      "one-sided (male < female), 5 %";
  const auto cycles = [&](const char* sex) {
    const auto it = times.sex_cycle.find(sex);
    return it == times.sex_cycle.end() ? decltype(it->second){} : it->second;
  };
  const auto male_cycles = cycles("male"), female_cycles = cycles("female");
  std::vector<double> male_means, female_means;
  for (const auto& [cycle, m] : male_cycles) {
    const auto f = female_cycles.find(cycle);
    if (f == female_cycles.end()) continue;
    male_means.push_back(m.first / m.second);
    female_means.push_back(f->second.first / f->second.second);
  }
  const auto count = [&](const char* sex) {
    const auto it = times.by_sex.find(sex);
    return it == times.by_sex.end() ? std::size_t{0} : it->second.size();
  };
  std::string why;
  const auto w = PairedIfDefined(
      male_means, female_means, "cycles completed by a male and a female operator", &why);
  if (!w) return UntestableClaim(claim, test, why);
  (*tests)["male_vs_female"] = {
      {"pairs", w->n},       {"mean_difference_s", w->mean_difference},
      {"t", w->t},           {"df", w->df},
      {"p_less", w->p_less}, {"p_two_sided", w->p_two_sided}};
  return Claim(
      claim, w->mean_difference < 0 && w->p_less < 0.05, test,
      fmt::format("male - female = {:.4f} s, 95 % CI [{:.4f}, {:.4f}], t = {:.3f}, "
                  "df = {:.0f}, p(male < female) = {:.4f}; {} paired cycles ({} "
                  "and {} completions)",
                  w->mean_difference, w->ci.lower, w->ci.upper, w->t, w->df, w->p_less,
                  w->n, count("male"), count("female")));
}

// The parts from the heaviest to the lightest (positions in the sequence).
std::vector<std::size_t> HeaviestFirst(const scene::Scene& scene) {
  std::vector<std::size_t> order(scene.sequence.size());
  for (std::size_t p = 0; p < order.size(); ++p) order[p] = p;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scene.parts[scene.sequence[a]].mass > scene.parts[scene.sequence[b]].mass;
  });
  return order;
}

// The times of parts a and b in the cycles that completed both.
std::pair<std::vector<double>, std::vector<double>> BothCompleted(
    const AssemblyTimes& times, std::size_t a, std::size_t b) {
  std::pair<std::vector<double>, std::vector<double>> out;
  for (const std::vector<double>& t : times.cycle_parts)
    if (!std::isnan(t[a]) && !std::isnan(t[b])) {
      out.first.push_back(t[a]);
      out.second.push_back(t[b]);
    }
  return out;
}

// Claim: time falls with mass and size, each part in the sequence against the
// next lighter one.
nlohmann::json MassClaim(const scene::Scene& scene, const AssemblyTimes& times,
                         nlohmann::json* tests) {
  const char* claim = "subassembly time falls with the part's mass and size";
  const char* test =
      "paired t test over the cycles that completed both parts, each part against the "
      "next lighter, one-sided, 5 %";
  const std::vector<std::size_t> order = HeaviestFirst(scene);
  bool falls = true;
  std::string evidence, untestable;
  if (order.size() < 2)
    untestable = "the scene assembles one part: nothing to compare it with";
  for (std::size_t k = 0; k + 1 < order.size() && untestable.empty(); ++k) {
    const std::string& hn = scene.parts[scene.sequence[order[k]]].name;
    const std::string& ln = scene.parts[scene.sequence[order[k + 1]]].name;
    const auto [heavy, light] = BothCompleted(times, order[k], order[k + 1]);
    const auto w = PairedIfDefined(
        heavy, light, "cycles that completed the " + hn + " and the " + ln, &untestable);
    if (!w) break;
    falls = falls && w->mean_difference > 0 && w->p_greater < 0.05;
    (*tests)["heavier_vs_lighter"].push_back({{"heavier", hn},
                                              {"lighter", ln},
                                              {"pairs", w->n},
                                              {"mean_difference_s", w->mean_difference},
                                              {"p_heavier_slower", w->p_greater}});
    evidence += fmt::format(
        "{} - {} = {:.4f} s [{:.4f}, {:.4f}] over {} cycles (p(heavier slower) = "
        "{:.4f}); ",
        hn, ln, w->mean_difference, w->ci.lower, w->ci.upper, w->n, w->p_greater);
  }
  return untestable.empty() ? Claim(claim, falls, test, evidence)
                            : UntestableClaim(claim, test, untestable);
}

}  // namespace

Section AssemblyTimeSection(const experiment::ExperimentRun& run) {
  const scene::Scene& scene = run.file->scene;
  const AssemblyTimes times = CollectTimes(run.run, scene.sequence.size());
  Section out;
  out.tables.emplace_back("assembly_time_cycles.csv", CyclesTable(run.run));
  DescribeOperators(run.run, times, &out);
  DescribeParts(scene, times, &out);
  nlohmann::json tests = nlohmann::json::object();
  nlohmann::json claims = nlohmann::json::array();
  claims.push_back(SexClaim(times, &tests));
  claims.push_back(MassClaim(scene, times, &tests));
  out.summary = {{"tests", tests}, {"claims", claims}};
  return out;
}

}  // namespace vahf::report
