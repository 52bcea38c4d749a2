// Paper Sec. 5.2 (Figs. 11-12): assembly time of the cylinder per operator and
// of each subassembly, the male-female comparison, and time against part mass.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "vahf/report/section.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {}  // namespace

Section AssemblyTimeSection(const experiment::ExperimentRun& run) {
  const scene::Scene& scene = run.file->scene;
  const experiment::DesignRun& d = run.run;
  Section out;
  out.kind = "assembly_time";
  out.tables.emplace_back("assembly_time_cycles.csv", CyclesTable(d));
  const std::size_t n_parts = scene.sequence.size();

  // Cycle times per operator and per sex; part times per part and sex.
  std::vector<std::vector<double>> by_operator(d.conditions.size());
  std::vector<int> attempted(d.conditions.size(), 0);
  std::map<std::string, std::vector<double>> by_sex;
  // Per sex, cycle -> (sum, count) of completed cycle times: cycle j of every
  // operator runs on the same streams, so the sexes' means of cycle j pair.
  std::map<std::string, std::map<std::uint64_t, std::pair<double, int>>> sex_cycle;
  std::map<std::string, std::vector<std::vector<double>>> part_by_sex;
  std::vector<std::vector<double>> part_all(n_parts);
  // Each cycle's part times (NaN: the part did not complete): a cycle's parts
  // are a pair for the part against part test.
  std::vector<std::vector<double>> cycle_parts;
  for (const experiment::CycleRecord& r : d.records) {
    cycle_parts.emplace_back(n_parts, NAN);
    const std::string& sex = d.conditions[r.condition].group;
    ++attempted[r.condition];
    auto& parts = part_by_sex[sex];
    parts.resize(n_parts);
    for (std::size_t p = 0; p < r.result.parts.size(); ++p) {
      const sim::TrialResult& t = r.result.parts[p].trial;
      if (t.status != sim::Status::kCompleted) continue;
      parts[p].push_back(t.completion_time);
      part_all[p].push_back(t.completion_time);
      cycle_parts.back()[p] = t.completion_time;
    }
    if (!r.result.completed) continue;
    by_operator[r.condition].push_back(r.result.time);
    by_sex[sex].push_back(r.result.time);
    auto& [sum, count] = sex_cycle[sex][r.cycle];
    sum += r.result.time;
    ++count;
  }

  Table operators({"operator", "sex", "height_m", "arm_length_m", "cycles", "completed",
                   "mean_time_s", "sd_s", "ci_lower_s", "ci_upper_s"});
  std::string md =
      "## Assembly time per operator (Sec. 5.2, Figs. 11-12)\n\n"
      "Virtual time of the whole cylinder (completed cycles), mean and 95 % t "
      "interval.\n\n"
      "| operator | sex | height (m) | arm (m) | completed | time (s) |\n"
      "| --- | --- | --- | --- | --- | --- |\n";
  std::string fig11;
  for (std::size_t c = 0; c < d.conditions.size(); ++c) {
    const experiment::Condition& cond = d.conditions[c];
    const stats::Summary s = stats::Summarize(by_operator[c]);
    operators.AddRow(
        {cond.name, cond.group, cond.scene->op.height, cond.scene->op.arm_length,
         std::int64_t{attempted[c]}, static_cast<std::int64_t>(s.n), s.mean.value_or(NAN),
         s.sd.value_or(NAN), s.ci ? s.ci->lower : NAN, s.ci ? s.ci->upper : NAN});
    md += fmt::format("| {} | {} | {:.3f} | {:.3f} | {}/{} | {} |\n", cond.name,
                      cond.group, cond.scene->op.height, cond.scene->op.arm_length, s.n,
                      attempted[c], MeanCi(s));
    if (s.mean)
      fig11 += fmt::format("{} \"{}\" {} {} {}\n", c, cond.name, *s.mean,
                           s.ci ? s.ci->lower : *s.mean, s.ci ? s.ci->upper : *s.mean);
  }
  out.tables.emplace_back("assembly_time_operators.csv", operators);

  // Subassemblies: time against mass (Fig. 12).
  Table parts({"position", "part", "mass_kg", "sex", "n", "mean_time_s", "ci_lower_s",
               "ci_upper_s"});
  md +=
      "\nSubassembly time (completed part trials), mean and 95 % interval, by sex:\n\n"
      "| part | mass (kg) | all | male | female |\n| --- | --- | --- | --- | --- |\n";
  std::string fig12;
  for (std::size_t p = 0; p < n_parts; ++p) {
    const scene::Part& part = scene.parts[scene.sequence[p]];
    std::string line = fmt::format("| {} | {:.3f} | {} |", part.name, part.mass,
                                   MeanCi(stats::Summarize(part_all[p])));
    fig12 += fmt::format("{} \"{}\"", p, part.name);
    for (const char* sex : {"male", "female"}) {
      const auto it = part_by_sex.find(sex);
      const std::vector<double> xs =
          it == part_by_sex.end() ? std::vector<double>{} : it->second[p];
      const stats::Summary s = stats::Summarize(xs);
      parts.AddRow({static_cast<std::int64_t>(p), part.name, part.mass, std::string(sex),
                    static_cast<std::int64_t>(s.n), s.mean.value_or(NAN),
                    s.ci ? s.ci->lower : NAN, s.ci ? s.ci->upper : NAN});
      line += " " + MeanCi(s) + " |";
      const double mean = s.mean.value_or(NAN);
      fig12 += fmt::format(" {} {} {}", mean, s.ci ? s.ci->lower : mean,
                           s.ci ? s.ci->upper : mean);
    }
    md += line + "\n";
    fig12 += "\n";
  }
  out.tables.emplace_back("assembly_time_parts.csv", parts);

  // Claims.
  nlohmann::json claims = nlohmann::json::array();
  nlohmann::json tests = nlohmann::json::object();
  const std::vector<double>& male = by_sex["male"];
  const std::vector<double>& female = by_sex["female"];
  const char* kSexClaim =
      "the male operators assemble the cylinder faster than the female ones";
  const char* kSexTest =
      "paired t test of the male and female operators' mean time of each cycle, "
      "one-sided "
      "(male < female), 5 %";
  std::vector<double> male_means, female_means;
  for (const auto& [cycle, m] : sex_cycle["male"]) {
    const auto f = sex_cycle["female"].find(cycle);
    if (f == sex_cycle["female"].end()) continue;
    male_means.push_back(m.first / m.second);
    female_means.push_back(f->second.first / f->second.second);
  }
  std::string why;
  if (const auto w =
          PairedIfDefined(male_means, female_means,
                          "cycles completed by a male and a female operator", &why)) {
    const bool ok = w->mean_difference < 0 && w->p_less < 0.05;
    claims.push_back(Claim(
        kSexClaim, ok, kSexTest,
        fmt::format("male - female = {:.4f} s, 95 % CI [{:.4f}, {:.4f}], t = {:.3f}, "
                    "df = {:.0f}, p(male < female) = {:.4f}; {} paired cycles ({} and {} "
                    "completions)",
                    w->mean_difference, w->ci.lower, w->ci.upper, w->t, w->df, w->p_less,
                    w->n, male.size(), female.size())));
    tests["male_vs_female"] = {
        {"pairs", w->n},       {"mean_difference_s", w->mean_difference},
        {"t", w->t},           {"df", w->df},
        {"p_less", w->p_less}, {"p_two_sided", w->p_two_sided}};
  } else {
    claims.push_back(UntestableClaim(kSexClaim, kSexTest, why));
  }
  // Time falls with mass and size: each part in the sequence (heaviest first in
  // this scene) against the next lighter one.
  std::vector<std::size_t> order(n_parts);
  for (std::size_t p = 0; p < n_parts; ++p) order[p] = p;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return scene.parts[scene.sequence[a]].mass > scene.parts[scene.sequence[b]].mass;
  });
  const char* kMassClaim = "subassembly time falls with the part's mass and size";
  const char* kMassTest =
      "paired t test over the cycles that completed both parts, each part against the "
      "next "
      "lighter, one-sided, 5 %";
  bool falls = true;
  std::string evidence, untestable;
  if (n_parts < 2)
    untestable = "the scene assembles one part: nothing to compare it with";
  for (std::size_t k = 0; k + 1 < order.size() && untestable.empty(); ++k) {
    const std::string& hn = scene.parts[scene.sequence[order[k]]].name;
    const std::string& ln = scene.parts[scene.sequence[order[k + 1]]].name;
    std::vector<double> heavy, light;
    for (const std::vector<double>& times : cycle_parts)
      if (!std::isnan(times[order[k]]) && !std::isnan(times[order[k + 1]])) {
        heavy.push_back(times[order[k]]);
        light.push_back(times[order[k + 1]]);
      }
    const auto w = PairedIfDefined(
        heavy, light, "cycles that completed the " + hn + " and the " + ln, &untestable);
    if (!w) break;
    falls = falls && w->mean_difference > 0 && w->p_greater < 0.05;
    tests["heavier_vs_lighter"].push_back({{"heavier", hn},
                                           {"lighter", ln},
                                           {"pairs", w->n},
                                           {"mean_difference_s", w->mean_difference},
                                           {"p_heavier_slower", w->p_greater}});
    evidence += fmt::format(
        "{} - {} = {:.4f} s [{:.4f}, {:.4f}] over {} cycles "
        "(p(heavier slower) = {:.4f}); ",
        hn, ln, w->mean_difference, w->ci.lower, w->ci.upper, w->n, w->p_greater);
  }
  claims.push_back(untestable.empty()
                       ? Claim(kMassClaim, falls, kMassTest, evidence)
                       : UntestableClaim(kMassClaim, kMassTest, untestable));
  out.summary = {{"tests", tests}, {"claims", claims}};
  out.markdown = md;
  out.plots.push_back(
      {"plots/assembly_time_operators.png",
       "Fig. 11: virtual assembly time of the cylinder per operator (mean, 95 % "
       "interval)",
       "$d << EOD\n" + fig11 +
           "EOD\nset title 'Assembly time of the hydraulic cylinder per operator'\n"
           "set ylabel 'time (s)'\nset xrange [-0.5:" +
           std::to_string(d.conditions.size()) +
           "-0.5]\nset yrange [0:*]\nset style fill solid 0.4\nset boxwidth 0.6\nset "
           "grid y\n"
           "plot $d using 1:3:xtic(2) with boxes notitle, '' using 1:3:4:5 with "
           "yerrorbars "
           "pt 7 lc black notitle\n"});
  out.plots.push_back(
      {"plots/assembly_time_parts.png",
       "Fig. 12: virtual time of each subassembly, male and female operators",
       "$d << EOD\n" + fig12 +
           "EOD\nset title 'Subassembly time (heaviest part first; mean, 95 % "
           "interval)'\n"
           "set ylabel 'time (s)'\nset yrange [0:*]\nset style data histograms\n"
           "set style histogram errorbars gap 1 lw 1\nset style fill solid 0.5\n"
           "set grid y\nplot $d using 3:4:5:xtic(2) title 'male', '' using 6:7:8 title "
           "'female'\n"});
  return out;
}

}  // namespace vahf::report
