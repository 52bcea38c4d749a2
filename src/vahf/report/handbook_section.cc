#include "vahf/report/handbook_section.h"

#include <fmt/format.h>

#include <cmath>
#include <string>
#include <vector>

#include "vahf/data/handbook_classification.h"
#include "vahf/report/markdown.h"
#include "vahf/report/section.h"
#include "vahf/stats/summary.h"

namespace vahf::report {
namespace {

// The sources of data/handbooks/README.md, as the report cites them.
constexpr const char* kSources =
    "Sources (data/handbooks/README.md gives what each shows and what it does not):\n\n"
    "- **S1** MTM Association e.V., *MTM-1 Data Card (SI - metric system)*, 2019, "
    "read as https://scribd.com/document/685645331/MTM-1-datacard-2019-EN (page 1 of 2): "
    "1 TMU = 0.036 s and the Position codes P1S-P2NS; **not** the Position table's "
    "times.\n"
    "- **S2** a transcription of the Boothroyd-Dewhurst manual insertion chart in a "
    "public C# design-for-assembly program (`Form1.cs`, `Insertion_and_Union`): every "
    "insertion time in data/handbooks/boothroyd_dewhurst_insertion.csv.\n"
    "- **S3** D. E. Whitney, *Mechanical Assemblies*, Oxford University Press, 2004, "
    "Ch. 15, Figs. 15-1 and 15-2 (courtesy of Boothroyd Dewhurst, Inc., 1999), read as "
    "an excerpt of p. 386: cross-checks S2's handling times and its 1.5 s for code 00 "
    "only.\n\n";

// What a part's trials in the run measured: the insertion proper (first
// contact to completion) of the completed trials that touched, the whole
// part trial of every completed one, and the completions without contact.
struct VirtualTimes {
  std::vector<double> insertion, whole;
  std::size_t attempted = 0, untouched = 0;
};

VirtualTimes TimesOf(const experiment::DesignRun& d, std::size_t position) {
  VirtualTimes t;
  for (const experiment::CycleRecord& r : d.records) {
    if (position >= r.result.parts.size()) continue;
    const sim::TrialResult& trial = r.result.parts[position].trial;
    ++t.attempted;
    if (trial.status != sim::Status::kCompleted) continue;
    t.whole.push_back(trial.completion_time);
    if (trial.first_contact_time < 0) {
      ++t.untouched;
      continue;
    }
    t.insertion.push_back(trial.completion_time - trial.first_contact_time);
  }
  return t;
}

std::string Seconds(const std::optional<double>& s, const std::string& source) {
  return s ? fmt::format("{:.2f} ({})", *s, source) : std::string("none");
}

// "mean [lo, hi] (sd s, n = N)": MeanCi with the spread and the count.
std::string Spread(const stats::Summary& s) {
  if (!s.mean) return "- (n = 0)";
  return fmt::format("{} (sd {:.3f}, n = {})", MeanCi(s), s.sd.value_or(0.0), s.n);
}

// One part's row in the Markdown, the CSV and the summary.
void DescribePart(const experiment::ExperimentRun& at, std::size_t position,
                  const data::BdInsertionTable& bd, const data::MtmPositionTable& mtm,
                  MarkdownTable* md, Table* csv, nlohmann::json* parts,
                  std::string* reasons) {
  const scene::Scene& scene = at.file->scene;
  const scene::Part& part =
      scene.parts[static_cast<std::size_t>(scene.sequence[position])];
  std::string fit_why;
  const std::optional<data::InsertionFit> fit =
      data::InsertionFitOf(scene, position, &fit_why);
  const VirtualTimes t = TimesOf(at.run, position);
  const stats::Summary ins = stats::Summarize(t.insertion);
  const stats::Summary whole = stats::Summarize(t.whole);
  data::HandbookClasses c;
  if (fit) c = data::ClassifyInsertion(*fit, mtm, bd);
  const data::BdInsertionTime* bd_row = fit ? bd.Find(c.bd.code) : nullptr;
  const data::MtmPositionTime* mtm_row = fit ? mtm.Find(c.mtm.code) : nullptr;
  const std::string bd_source = bd_row ? bd_row->source : "";
  const std::string mtm_source = mtm_row ? mtm_row->source : "";
  md->AddRow({part.name, fit ? c.bd.code : "-", Seconds(c.bd.seconds, bd_source),
              fit ? c.mtm.code : "-", Seconds(c.mtm.seconds, mtm_source), Spread(ins),
              Spread(whole)});
  csv->AddRow({static_cast<std::int64_t>(position), part.name, fit ? c.bd.code : "",
               c.bd.seconds.value_or(NAN), bd_source, fit ? c.mtm.code : "",
               c.mtm.seconds.value_or(NAN), mtm_source,
               static_cast<std::int64_t>(t.attempted), static_cast<std::int64_t>(ins.n),
               static_cast<std::int64_t>(t.untouched), ins.mean.value_or(NAN),
               ins.sd.value_or(NAN), whole.mean.value_or(NAN)});
  parts->push_back({{"part", part.name},
                    {"fit", fit_why},
                    {"boothroyd_dewhurst",
                     {{"code", fit ? c.bd.code : ""},
                      {"why", c.bd.why},
                      {"seconds", c.bd.seconds.value_or(NAN)},
                      {"source", bd_source}}},
                    {"mtm1",
                     {{"code", fit ? c.mtm.code : ""},
                      {"why", c.mtm.why},
                      {"seconds", c.mtm.seconds.value_or(NAN)},
                      {"source", mtm_source}}},
                    {"insertion_n", ins.n},
                    {"insertion_mean_s", ins.mean.value_or(NAN)},
                    {"insertion_sd_s", ins.sd.value_or(NAN)},
                    {"completed_without_contact", t.untouched}});
  *reasons += fmt::format("- **{}**: {}.", part.name, fit_why);
  if (fit)
    *reasons += fmt::format(" Boothroyd-Dewhurst {}: {}. MTM-1 {}: {}.", c.bd.code,
                            c.bd.why, c.mtm.code, c.mtm.why);
  if (t.untouched > 0)
    *reasons += fmt::format(
        " {} completed trial(s) never touched a fixed part and have no insertion time.",
        t.untouched);
  *reasons += "\n";
}

}  // namespace

Section HandbookSection(const experiment::ExperimentRun* times,
                        const data::BdInsertionTable& bd,
                        const data::MtmPositionTable& mtm) {
  Section out;
  out.kind = "handbooks";
  out.markdown =
      "## Handbooks: virtual insertion time beside Boothroyd-Dewhurst and "
      "MTM-1\n\n";
  nlohmann::json parts = nlohmann::json::array();
  const experiment::ExperimentRun* at = times;
  if (!at) {
    out.markdown +=
        "The run has no experiment that times the parts (assembly_time): no part's "
        "virtual "
        "insertion time to set beside the handbooks.\n\n";
  } else {
    out.markdown += fmt::format(
        "Each part of the {} experiment's sequence (scene `{}`, at the run's "
        "parameters), "
        "classed from the scene's geometry by the rules of docs/handbooks.md. The "
        "virtual insertion time is that of the handbooks' insertion: from the first "
        "decision instant at which the part touches a fixed part (the part at the hole; "
        "acquisition and transport, the handbooks' handling and Move/Reach, are left "
        "out) to its completion: mean [95 % t interval] (sample sd, n completed "
        "trials that touched), over all operators and cycles of the experiment; the "
        "whole "
        "part trial (start to completion) beside it. Times in seconds; each handbook "
        "time with its source id.\n\n",
        at->file->name, at->file->scene_path);
    MarkdownTable md{{"part", "B-D code", "B-D time (s)", "MTM-1 code", "MTM-1 time (s)",
                      "virtual insertion (s)", "whole part trial (s)"}};
    Table csv({"position", "part", "bd_code", "bd_s", "bd_source", "mtm_code", "mtm_s",
               "mtm_source", "trials", "insertion_n", "completed_without_contact",
               "insertion_mean_s", "insertion_sd_s", "part_trial_mean_s"});
    std::string reasons;
    for (std::size_t p = 0; p < at->file->scene.sequence.size(); ++p)
      DescribePart(*at, p, bd, mtm, &md, &csv, &parts, &reasons);
    out.markdown +=
        ToMarkdown(md) + "\nWhich class each part took, and why:\n\n" + reasons + "\n";
    out.tables.emplace_back("handbooks.csv", std::move(csv));
  }
  out.markdown +=
      "**Unverified values.** Every Boothroyd-Dewhurst time is S2's transcription; only "
      "code 00's 1.5 s is cross-checked (S3). The MTM-1 classes' names (1 loose, 2 "
      "close, "
      "3 exact) are the issue's reading of the data card, not read in S1, and the "
      "close/loose threshold (2/1000 of the diameter) is vahf's choice.\n\n";
  if (mtm.rows.empty())
    out.markdown += fmt::format(
        "**No MTM-1 time is shown**: `{}` has no rows, because no document read shows "
        "the Position table's times (S1's readable page stops before it); a time goes in "
        "only with the document that shows it.\n\n",
        mtm.file);
  out.markdown += kSources;
  out.summary = {{"claims", nlohmann::json::array()},
                 {"parts", parts},
                 {"mtm1_rows", mtm.rows.size()}};
  return out;
}

}  // namespace vahf::report
