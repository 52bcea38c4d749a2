#include "vahf/kinds/verify.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <system_error>

#include "vahf/core/error.h"
#include "vahf/core/temporary_directory.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/recorded_run.h"
#include "vahf/report/manifest.h"
#include "vahf/report/output_directory.h"
#include "vahf/report/result_diff.h"

namespace vahf::kinds {
namespace {

namespace fs = std::filesystem;

// A directory made for the re-run, removed with everything in it unless
// the user asked to keep the output.
class RerunDirectory {
 public:
  explicit RerunDirectory(const std::string& keep) {
    if (!keep.empty()) {
      output_ = keep;
      return;
    }
    temporary_.emplace("vahf-verify");
    output_ = temporary_->path() + "/rerun";
  }
  const std::string& output() const { return output_; }

 private:
  std::optional<TemporaryDirectory> temporary_;
  std::string output_;
};

// Runs the recorded invocation into `out`; its own lines go to stdout.
void Rerun(const report::RecordedRun& run, int threads, const std::string& out) {
  const scene::ExperimentFile file = LoadRecordedExperiment(run);
  RunContext context;
  context.settings = RecordedSettings(run, threads);
  report::OutputDirectory directory(out);
  context.directory = &directory;
  RunExperiment(file, context);  // a plot it could not render is no result
}

// Each result file of the run against the re-run's: the first difference,
// and how many files differ. Files the re-run wrote that the run did not
// list count as differing too.
int CompareResults(const report::RecordedRun& run, const std::string& rerun_dir) {
  const report::RecordedRun again = report::ReadManifest(rerun_dir + "/manifest.json");
  std::vector<std::string> names = run.result_files;
  for (const std::string& name : again.result_files)
    if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  std::sort(names.begin(), names.end());
  std::string first;
  int differing = 0;
  for (const std::string& name : names) {
    const std::optional<std::string> recorded =
        ReadResultFile(fs::path(run.file).parent_path().string(), name);
    const std::optional<std::string> rerun = ReadResultFile(rerun_dir, name);
    std::string what;
    if (!recorded) {
      what = name + (rerun ? ": missing from the run directory" : ": missing from both");
    } else if (!rerun) {
      what = name + ": the run wrote it, the re-run did not";
    } else if (const auto d = report::FirstDifference(name, *recorded, *rerun)) {
      what = d->Text();
    } else {
      continue;
    }
    if (differing++ == 0) first = what;
  }
  if (differing == 0 && again.results_digest == run.results_digest) {
    std::printf("verify: identical: %zu result files, results digest %s\n", names.size(),
                run.results_digest.c_str());
    return 0;
  }
  if (differing == 0)  // the files agree but the manifest's digest does not
    first = fmt::format("manifest.json: results digest {} in the run, {} in the re-run",
                        run.results_digest, again.results_digest);
  std::printf("verify: different: %s (%d of %zu result files differ)\n", first.c_str(),
              differing, names.size());
  return 1;
}

}  // namespace

int Verify(const VerifyOptions& options) {
  const report::RecordedRun run = ReadRecordedRun(options.run_dir);
  std::error_code error;
  std::printf("verify %s: %zu inputs as the run read them (SHA-256)\n",
              options.run_dir.c_str(), run.inputs.size());
  const std::vector<std::string> build = report::BuildDifferences(run.build);
  if (build.empty()) std::printf("build: the run's\n");
  for (const std::string& line : build) std::printf("build differs: %s\n", line.c_str());
  // Whether the files still give the manifest's digest: an edit after the run
  // shows here before any re-run.
  bool stored_complete = true;
  for (const std::string& name : run.result_files)
    stored_complete =
        stored_complete && fs::is_regular_file(fs::path(options.run_dir) / name, error);
  if (!stored_complete || report::ResultsDigestOfFiles(
                              options.run_dir, run.result_files) != run.results_digest)
    std::printf(
        "the run directory's result files no longer give its manifest's results digest "
        "(changed since the run)\n");
  const int threads = options.threads > 0 ? options.threads : run.threads;
  const report::Invocation& i = run.invocation;
  std::string how = fmt::format("seed {}", i.seed);
  if (i.trials > 0) how += fmt::format(", --trials {}", i.trials);
  if (!i.overrides.empty()) how += ", --overrides " + i.overrides;
  std::printf(
      "re-running %s, %s, on %d thread(s)%s\n", i.experiment.c_str(), how.c_str(),
      threads,
      run.ranks > 1
          ? fmt::format(" in one process (the run had {} MPI ranks)", run.ranks).c_str()
          : "");
  std::fflush(stdout);
  const RerunDirectory rerun(options.keep);
  Rerun(run, threads, rerun.output());
  if (!options.keep.empty()) std::printf("re-run kept in %s\n", options.keep.c_str());
  return CompareResults(run, rerun.output());
}

}  // namespace vahf::kinds
