#include "vahf/report/run_output.h"

#include <fmt/format.h>

#include <map>

#include "vahf/core/error.h"
#include "vahf/report/manifest.h"
#include "vahf/report/markdown.h"
#include "vahf/report/output_directory.h"
#include "vahf/report/plot.h"
#include "vahf/report/section.h"

namespace vahf::report {
namespace {

// The runs whose sections the output holds: the run itself, or a paper's parts.
std::vector<const experiment::ExperimentRun*> Leaves(
    const experiment::ExperimentRun& run) {
  std::vector<const experiment::ExperimentRun*> out;
  if (run.parts.empty()) {
    out.push_back(&run);
  } else {
    for (const auto& p : run.parts) out.push_back(&p);
  }
  return out;
}

// The scene files and other inputs (a paper table) an experiment read, each
// once, in the order first met.
void AddInputs(const scene::ExperimentFile& f, std::vector<std::string>* paths) {
  const auto add = [&](const std::string& p) {
    if (!p.empty() && std::find(paths->begin(), paths->end(), p) == paths->end())
      paths->push_back(p);
  };
  add(f.scene_path);
  if (f.input)
    for (const std::string& p : f.input->InputFiles()) add(p);
  add(f.overrides_path);
}

// "10", or for a paper run each experiment's: "table1 8, fatigue 12", or for
// a design whose conditions carry their own cycles, each group's (a precision
// run's scenes): "hydraulic_cylinder 3, peg_in_hole 8".
std::string CyclesPerCondition(const experiment::ExperimentRun& run) {
  if (!run.run.conditions.empty() && run.run.conditions.front().trials > 0) {
    std::string out;
    std::string last;
    for (const experiment::Condition& c : run.run.conditions) {
      if (c.group == last) continue;
      last = c.group;
      out += fmt::format("{}{} {}", out.empty() ? "" : ", ", c.group, c.trials);
    }
    return out;
  }
  if (run.parts.empty()) return std::to_string(run.trials);
  std::string out;
  for (const auto& p : run.parts)
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", p.file->name, p.trials);
  return out;
}

// The claims of every section; nothing when no section tests one (precision).
std::string ClaimsMarkdown(const std::vector<Section>& sections) {
  bool any = false;
  for (const Section& s : sections) any = any || !s.summary.at("claims").empty();
  if (!any) return "";
  MarkdownTable table{{"claim", "reproduced", "test", "evidence"}};
  for (const Section& s : sections)
    for (const auto& c : s.summary.at("claims"))
      table.AddRow({c.at("claim").get<std::string>(),
                    c.at("verdict") == "no" ? std::string("**no**")
                                            : c.at("verdict").get<std::string>(),
                    c.at("test").get<std::string>(),
                    c.at("evidence").get<std::string>()});
  const std::string md =
      "## The paper's claims\n\nEach claim is tested on the run: yes, no, or untestable "
      "(the run cannot test it; the evidence says why).\n\n" +
      ToMarkdown(table);
  return md + "\n";
}

}  // namespace

std::string IntegrationText(const scene::Parameters& p) {
  return fmt::format("{} at accuracy {:g}, contact model {}", p.simulation.integrator,
                     p.simulation.accuracy, p.contact.model);
}

RunOutput WriteRunOutput(const experiment::ExperimentRun& run,
                         const std::vector<Section>& sections, OutputDirectory& out,
                         const RunInfo& info) {
  // A section per experiment run, then a run of experiments' own (a paper
  // run's handbooks).
  VAHF_CHECK(sections.size() >= Leaves(run).size(), "a section per experiment run");
  RunHeader h;
  h.file = run.file;
  h.first = run.parts.empty() ? run.file : run.parts[0].file;
  h.seed = run.seed;
  h.trials = run.trials;
  h.cycles_per_condition = CyclesPerCondition(run);
  for (const experiment::ExperimentRun* leaf : Leaves(run)) {
    const std::string one = IntegrationText(leaf->file->scene.params);
    if (h.integration.find(one) == std::string::npos)
      h.integration += (h.integration.empty() ? "" : "; ") + one;
    if (leaf != &run) h.inputs.push_back(leaf->file->file);
    AddInputs(*leaf->file, &h.inputs);
  }
  for (const auto& part : run.parts)
    h.experiments.push_back(
        {{"name", part.file->name}, {"kind", part.file->kind}, {"trials", part.trials}});
  return WriteSections(h, sections, out, info);
}

namespace {

// The result files (the tables, the other files, summary.json), written and
// digested; returns the digest and names them in `names`.
std::string WriteResults(const RunHeader& h, const std::vector<Section>& sections,
                         OutputDirectory& out, std::vector<std::string>* names,
                         std::map<std::string, std::string>* results) {
  nlohmann::json summary = {{"experiment", h.file->name},
                            {"kind", h.file->kind},
                            {"seed", h.seed},
                            {"trials", h.trials}};
  for (const Section& s : sections) {
    for (const auto& [name, table] : s.tables) (*results)[name] = table.ToCsv();
    for (const auto& [name, bytes] : s.files) (*results)[name] = bytes;
    summary["sections"][s.kind] = s.summary;
  }
  (*results)["summary.json"] = summary.dump(1) + "\n";
  for (const auto& [name, bytes] : *results) {
    out.Write(name, bytes);
    names->push_back(name);
  }
  return ResultsDigest(*results);
}

// The measured files (tables and measured.json), written, never digested.
std::vector<std::string> WriteMeasured(const std::vector<Section>& sections,
                                       const std::map<std::string, std::string>& results,
                                       OutputDirectory& out) {
  std::vector<std::string> names;
  nlohmann::json measured;
  for (const Section& s : sections) {
    for (const auto& [name, table] : s.measured_tables) {
      VAHF_CHECK(!results.count(name), "a measured file is named as a result file");
      out.Write(name, table.ToCsv());
      names.push_back(name);
    }
    if (!s.measured.is_null()) measured["sections"][s.kind] = s.measured;
  }
  if (!measured.is_null()) {
    out.Write("measured.json", measured.dump(1) + "\n");
    names.push_back("measured.json");
  }
  return names;
}

// The manifest: the experiment file, the first scene, and every file read.
nlohmann::json Manifest(const RunHeader& h, const RunInfo& info, ManifestFields* m,
                        const std::vector<std::string>& measured_files) {
  m->invocation = {h.file->file, h.file->overrides_path, h.seed, info.trials_option};
  m->experiment = DescribeInputFile(h.file->file);
  m->scene = DescribeInputFile(h.first->scene_path);
  m->seed = h.seed;
  m->trials = h.trials;
  m->threads = info.threads;
  m->ranks = info.ranks;
  m->parameters = h.first->scene.params;
  nlohmann::json manifest = ManifestJson(*m);
  for (const std::string& p : h.inputs) {
    const InputFile f = DescribeInputFile(p);
    manifest["inputs"].push_back({{"path", f.path}, {"sha256", f.sha256}});
  }
  if (!measured_files.empty()) manifest["measured_files"] = measured_files;
  if (!h.experiments.is_null()) manifest["experiments"] = h.experiments;
  return manifest;
}

// A section in report.md: its Markdown, each plot rendered (or why it is
// missing, also added to `failed`), and the files it wrote.
std::string SectionMarkdown(const Section& s, OutputDirectory& out,
                            std::vector<std::string>* failed) {
  std::string md = s.markdown + "\n";
  for (const Plot& p : s.plots) {
    try {
      RenderPlot(p.script, out.Path(p.file));
      md += fmt::format("![{}]({})\n\n*{}*\n\n", p.title, p.file, p.title);
    } catch (const PlotError& e) {
      failed->push_back(p.file + ": " + e.what());
      md += fmt::format("**Figure missing:** {} (`{}`) could not be rendered: {}\n\n",
                        p.title, p.file, e.what());
    }
  }
  md += "Tables: ";
  std::size_t k = 0;
  for (const auto& [name, table] : s.tables)
    md += fmt::format("{}`{}`", k++ ? ", " : "", name);
  for (const auto& [name, bytes] : s.files)
    md += fmt::format("{}`{}`", k++ ? ", " : "", name);
  for (const auto& [name, table] : s.measured_tables)
    md += fmt::format(", `{}` (measured, outside the digest)", name);
  if (!s.measured.is_null()) md += ", `measured.json` (measured, outside the digest)";
  return md + ".\n\n";
}

}  // namespace

RunOutput WriteSections(const RunHeader& h, const std::vector<Section>& sections,
                        OutputDirectory& out, const RunInfo& info) {
  RunOutput result;
  const scene::ExperimentFile& file = *h.file;
  std::map<std::string, std::string> results;  // name -> bytes, for the digest
  ManifestFields m;
  const std::string digest = WriteResults(h, sections, out, &m.result_files, &results);
  m.results_digest = digest;
  const std::vector<std::string> measured_files = WriteMeasured(sections, results, out);
  out.Write(OutputDirectory::kMarkerFile,
            Manifest(h, info, &m, measured_files).dump(1) + "\n");

  // Report: what ran, the claims, then each section with its plots.
  std::string md = fmt::format(
      "# vahf report: {}\n\n{}\n\n"
      "- experiment file: `{}` (kind {}), seed {}, cycles per condition: {}\n"
      "- integration: {} (the scenes' simulation/integrator, simulation/accuracy and "
      "contact/model; docs/experiments.md, precision, measures the error they buy)\n"
      "- threads: {}{}, wall time: {:.1f} s (not part of any result file)\n"
      "- results digest (SHA-256 over the CSV tables and summary.json): `{}`\n"
      "- program: {} ({}), {} {}\n\n",
      file.name, file.description, file.file, file.kind, h.seed, h.cycles_per_condition,
      h.integration, info.threads,
      info.ranks > 1 ? fmt::format(" on each of {} MPI ranks", info.ranks) : "",
      info.wall_seconds, digest, m.build.version, m.build.git_describe,
      m.build.compiler_id, m.build.compiler_version);
  md += ClaimsMarkdown(sections);
  for (const Section& s : sections) md += SectionMarkdown(s, out, &result.failed_plots);
  out.Write("report.md", md);
  out.Commit();
  result.results_digest = digest;
  return result;
}

}  // namespace vahf::report
