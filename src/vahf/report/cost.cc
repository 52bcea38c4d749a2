#include "vahf/report/cost.h"

#include <fmt/format.h>

#include <variant>
#include <vector>

#include "vahf/report/markdown.h"
#include "vahf/stats/distribution.h"

namespace vahf::report {
namespace {

struct PartCost {
  std::string part;
  std::vector<double> cpu, simulated, rtf;
};

}  // namespace

Table CostTable(const experiment::DesignRun& run) {
  std::vector<PartCost> parts;
  for (const experiment::CycleRecord& r : run.records)
    for (const experiment::PartRun& p : r.result.parts) {
      PartCost* cost = nullptr;
      for (PartCost& c : parts)
        if (c.part == p.trial.part) cost = &c;
      if (!cost) cost = &parts.emplace_back(PartCost{p.trial.part, {}, {}, {}});
      cost->cpu.push_back(p.trial.cpu_seconds);
      cost->simulated.push_back(p.trial.end_time);
      if (p.trial.cpu_seconds > 0)
        cost->rtf.push_back(p.trial.end_time / p.trial.cpu_seconds);
    }
  Table t({"part", "trials", "cpu_p50_s", "cpu_p99_s", "cpu_max_s", "cpu_total_s",
           "simulated_mean_s", "rtf_p50"});
  for (const PartCost& c : parts) {
    double total = 0, simulated = 0;
    for (double x : c.cpu) total += x;
    for (double x : c.simulated) simulated += x;
    const double n = static_cast<double>(c.cpu.size());
    t.AddRow({c.part, static_cast<std::int64_t>(c.cpu.size()),
              stats::Quantile(c.cpu, 0.5), stats::Quantile(c.cpu, 0.99),
              stats::Quantile(c.cpu, 1.0), total, simulated / n,
              c.rtf.empty() ? 0.0 : stats::Quantile(c.rtf, 0.5)});
  }
  return t;
}

nlohmann::json CostJson(const Table& cost) {
  nlohmann::json parts = nlohmann::json::array();
  for (std::size_t r = 0; r < cost.rows(); ++r) {
    nlohmann::json row;
    for (std::size_t c = 0; c < cost.columns().size(); ++c)
      std::visit([&](const auto& v) { row[cost.columns()[c]] = v; }, cost.at(r, c));
    parts.push_back(row);
  }
  return {{"parts", parts}};
}

std::string CostMarkdown(const Table& cost) {
  MarkdownTable md({"part", "trials", "CPU p50 (s)", "CPU p99 (s)", "CPU max (s)",
                    "CPU total (s)", "simulated mean (s)", "real-time factor p50"});
  for (std::size_t r = 0; r < cost.rows(); ++r) {
    const auto number = [&](std::size_t c, int digits) {
      return fmt::format("{:.{}f}", std::get<double>(cost.at(r, c)), digits);
    };
    md.AddRow({std::get<std::string>(cost.at(r, 0)),
               std::to_string(std::get<std::int64_t>(cost.at(r, 1))), number(2, 3),
               number(3, 3), number(4, 3), number(5, 1), number(6, 3), number(7, 2)});
  }
  return "\n### Cost per trial\n\nMeasured on this machine (outside the results "
         "digest): the CPU seconds of each part's trials (the trial's thread, so "
         "independent of the thread count), and the real-time factor, simulated over CPU "
         "seconds.\n\n" +
         ToMarkdown(md);
}

}  // namespace vahf::report
