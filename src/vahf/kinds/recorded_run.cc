#include "vahf/kinds/recorded_run.h"

#include <fmt/format.h>

#include <filesystem>
#include <system_error>

#include "vahf/core/digest.h"
#include "vahf/core/error.h"
#include "vahf/core/whole_file.h"
#include "vahf/kinds/kind.h"

namespace vahf::kinds {

namespace fs = std::filesystem;

report::RecordedRun ReadRecordedRun(const std::string& run_dir) {
  std::error_code error;
  if (!fs::is_directory(run_dir, error))
    throw InputError(run_dir, "", "", "is not a directory (a run's output)");
  const report::RecordedRun run =
      report::ReadManifest((fs::path(run_dir) / "manifest.json").string());
  for (const report::RecordedRun::Input& in : run.inputs) {
    if (!fs::is_regular_file(in.file.path, error))
      throw InputError(run.file, in.pointer, in.file.sha256,
                       fmt::format("the input {} is missing (the run's inputs are read "
                                   "by their recorded paths, from the directory the "
                                   "command is started in)",
                                   in.file.path));
    const std::string now = Sha256OfFile(in.file.path);
    if (now != in.file.sha256)
      throw InputError(run.file, in.pointer, in.file.sha256,
                       fmt::format("the input {} now has SHA-256 {}: it changed since "
                                   "the run, so the run cannot be repeated from it",
                                   in.file.path, now));
  }
  return run;
}

scene::ExperimentFile LoadRecordedExperiment(const report::RecordedRun& run) {
  return LoadExperiment(run.invocation.experiment, run.invocation.overrides);
}

std::optional<std::string> ReadResultFile(const std::string& run_dir,
                                          const std::string& name) {
  const fs::path path = fs::path(run_dir) / name;
  std::error_code error;
  if (!fs::is_regular_file(path, error)) return std::nullopt;  // a result is a file
  return ReadWholeFile(path.string());
}

experiment::RunSettings RecordedSettings(const report::RecordedRun& run, int threads) {
  experiment::RunSettings settings;
  settings.seed = run.invocation.seed;
  settings.trials = static_cast<int>(run.invocation.trials);
  settings.threads = threads;
  return settings;
}

}  // namespace vahf::kinds
