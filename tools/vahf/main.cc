// The vahf command: validates scene, experiment and lab dataset files, checks
// the paper's reference values, and (as the harness grows) runs trials and
// experiments.
// Exit status, by the tiers of vahf/core/error.h: 0 success; 1 a failure of
// the computation, stated on stderr (for `vahf trial`: the trial ended other
// than completed, its summary still printed); 2 bad input (a file, a value or
// an option), in one line; 130 interrupted.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <exception>
#include <limits>
#include <memory>
#include <optional>
#include <string>

#include "vahf/core/atomic_file.h"
#include "vahf/core/error.h"
#include "vahf/core/temporary_directory.h"
#include "vahf/experiment/interrupt.h"
#include "vahf/experiment/launched_ranks.h"
#include "vahf/experiment/table1_reference.h"
#include "vahf/kinds/check_file.h"
#include "vahf/kinds/kind.h"
#include "vahf/kinds/replay.h"
#include "vahf/kinds/run_support.h"
#include "vahf/kinds/synthesize.h"
#include "vahf/kinds/trial_request.h"
#include "vahf/kinds/verify.h"
#include "vahf/report/output_directory.h"
#include "vahf/scene/experiment_file.h"
#include "vahf/scene/overrides.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/stepper_catalogue.h"
#include "vahf/sim/trace_csv.h"
#include "vahf/sim/trial.h"

namespace {

int Check(const std::string& path) {
  std::fputs(vahf::kinds::CheckFile(path).c_str(), stdout);
  return 0;
}

int Reference(const std::string& table_path) {
  const vahf::experiment::Table1 table = vahf::experiment::LoadTable1(table_path);
  const auto checks = vahf::experiment::CheckTable1(table);
  std::fputs(vahf::experiment::FormatTable1Check(table, checks).c_str(), stdout);
  return 0;
}

struct TrialArgs {
  std::string scene;
  std::uint64_t seed = 1;
  std::uint64_t trial = 0;
  int position = 0;
  std::string integrator;
  std::string accuracy;
  std::vector<std::string> sets;  // "group/key=value"
  std::string trace;
  double sample = 0;
};

int Trial(const TrialArgs& a) {
  vahf::kinds::TrialRequest request;
  request.seed = a.seed;
  request.trial = a.trial;
  request.position = a.position;
  request.integrator = a.integrator;
  request.accuracy = a.accuracy;
  request.sets = vahf::kinds::SplitParameterSets(a.sets);
  request.record_trace = !a.trace.empty();
  request.sample = a.sample;
  const vahf::sim::TrialResult r =
      vahf::kinds::RunTrialRequest(vahf::kinds::LoadSceneFile(a.scene), a.scene, request);
  if (!a.trace.empty()) vahf::WriteFileAtomically(a.trace, vahf::sim::TraceCsv(r));
  std::fputs(r.BriefReport().c_str(), stdout);
  if (!a.trace.empty())
    std::printf("trace: %s (%zu decision rows, %zu sample rows)\n", a.trace.c_str(),
                r.trace.size(), r.samples.size());
  if (r.status == vahf::sim::Status::kCompleted) return 0;
  // Anything else is not what a trial is for: say so on one line, exit 1.
  std::string detail = r.detail;
  std::replace(detail.begin(), detail.end(), '\n', ' ');  // Simbody's texts span lines
  std::fprintf(stderr, "vahf: trial ended %s: %s\n", vahf::sim::StatusName(r.status),
               detail.c_str());
  return vahf::kExitComputationFailure;
}

struct RunArgs {
  std::string experiment;
  std::string overrides;
  std::uint64_t seed = 0;
  bool seed_given = false;
  int trials = 0;
  int threads = 1;
  std::string out;
  bool resume = false;
};

// `ranks`: the MPI job's, when launched in one (launched_ranks.h). Every rank
// runs the whole command; rank 0 writes the output, the others write theirs
// into a temporary directory of their own, removed at the end, and every
// rank ends with rank 0's status.
int Run(const RunArgs& a, const vahf::experiment::Ranks* ranks) {
  std::optional<vahf::scene::ExperimentFile> file;
  vahf::kinds::RunContext context;
  std::optional<vahf::TemporaryDirectory> own;
  std::optional<vahf::report::OutputDirectory> staged;
  // The inputs read and the output checked and staged before any
  // simulation: a refused path costs nothing. With several ranks, one rank's
  // refusal (rank 0's output path, another's temporary directory) stops
  // every rank alike.
  const auto prepare = [&] {
    file = vahf::kinds::LoadExperiment(a.experiment, a.overrides);
    context.settings.seed = a.seed_given ? a.seed : file->seed;
    context.settings.trials = a.trials;
    context.settings.threads = a.threads;
    context.settings.ranks = ranks;
    std::string out = a.out.empty()
                          ? vahf::kinds::DefaultRunDirectory(*file, context.settings.seed)
                          : a.out;
    bool resume = a.resume;
    if (ranks && ranks->rank() != 0) {
      own.emplace("vahf-rank" + std::to_string(ranks->rank()));
      out = own->path() + "/out";
      resume = false;  // rank 0 keeps the journal
      context.settings.progress = false;
    }
    staged.emplace(out, resume);
  };
  vahf::experiment::AllAgree(ranks, prepare);
  vahf::report::OutputDirectory& directory = *staged;
  context.directory = &directory;
  vahf::experiment::InstallInterruptHandler();
  try {
    int status = vahf::kinds::RunExperiment(*file, context);
    if (a.resume)
      std::printf("resumed: %lld results taken from the journal, %lld computed\n",
                  static_cast<long long>(directory.Journaled().reused),
                  static_cast<long long>(directory.Journaled().written));
    // Rank 0's status: another rank's plot that gnuplot could not render
    // is no failure of the run.
    if (ranks && ranks->size() > 1)
      status = std::stoi(ranks->AllGather(std::to_string(status))[0]);
    return status;
  } catch (const vahf::experiment::Interrupted& e) {
    if (directory.Journaled().total() == 0) throw;
    throw vahf::experiment::Interrupted(fmt::format(
        "{}; its {} finished results are journaled in {} (the same command with "
        "--resume continues the run)",
        e.what(), directory.Journaled().total(), directory.staging()));
  }
}

struct SynthesizeArgs {
  std::string generator;
  std::string out;
  int threads = 1;
};

int Synthesize(const SynthesizeArgs& a) {
  vahf::experiment::RunnerOptions options;
  options.threads = a.threads;
  vahf::experiment::InstallInterruptHandler();
  std::fputs(vahf::kinds::Synthesize(a.generator, a.out, options).c_str(), stdout);
  return 0;
}

}  // namespace

// Joins the MPI job this process was launched in, if any (launched_ranks.h).
// A rank other than 0 prints nothing: rank 0 prints the same lines.
std::unique_ptr<vahf::experiment::Ranks> JoinRanks(int* argc, char*** argv) {
  std::unique_ptr<vahf::experiment::Ranks> ranks =
      vahf::experiment::JoinLaunchedRanks(argc, argv);
  if (ranks && ranks->rank() != 0 && !std::freopen("/dev/null", "w", stdout))
    throw vahf::ComputationError(vahf::ComputationError::Reason::kRefused,
                                 "cannot send rank " + std::to_string(ranks->rank()) +
                                     "'s standard output to /dev/null");
  return ranks;
}

int main(int argc, char** argv) {
  std::unique_ptr<vahf::experiment::Ranks> ranks;
  try {
    ranks = JoinRanks(&argc, &argv);
  } catch (const vahf::InputError& e) {
    std::fprintf(stderr, "vahf: error: %s\n", e.what());
    return vahf::kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "vahf: error: %s\n", e.what());
    return vahf::kExitComputationFailure;
  }
  // Ends with an error. With several ranks, one every rank met alike (the
  // command line, or agreed: ranks.h) is said by rank 0, and the ranks end
  // normally; one this rank met alone is said with its rank and ends the job,
  // which would otherwise wait for this rank forever.
  const auto fail = [&ranks](int status, const char* prefix, const char* what,
                             const char* suffix = "", bool alike = false) {
    const bool several = ranks && ranks->size() > 1;
    if (several && !alike && !vahf::experiment::ErrorAgreedByAllRanks()) {
      std::fprintf(stderr, "vahf (rank %d of %d): %s: %s%s\n", ranks->rank(),
                   ranks->size(), prefix, what, suffix);
      std::fflush(stderr);
      ranks->Abort(status);
    }
    if (!several || ranks->rank() == 0)
      std::fprintf(stderr, "vahf: %s: %s%s\n", prefix, what, suffix);
    return status;
  };

  CLI::App app{
      "vahf: a deterministic, seeded validation harness for physics-based virtual "
      "assembly with human factors"};
  app.set_version_flag("--version", "vahf 0.1.0");
  app.require_subcommand(1);
  app.footer(
      "Exit status: 0 success; 1 a failure of the computation, stated on stderr (trial: "
      "the "
      "trial did not complete); 2 bad input (a file, a value or an option), one line; "
      "130 "
      "interrupted.");

  // Command-line integers, read strictly: decimal digits only, from 0 to
  // `max`, rewritten in canonical form for CLI11's own conversion (CLI11 2.1
  // reads them with strtoull(text, 0): "-1" would wrap to 2^64 - 1, "010" be
  // octal 8 and "0x10" hexadecimal).
  const auto decimal = [](std::uint64_t max) {
    return CLI::Validator(
        [max](std::string& text) {
          std::uint64_t v = 0;
          const char* end = text.data() + text.size();
          const auto [stop, error] = std::from_chars(text.data(), end, v);
          if (text.empty() || error != std::errc() || stop != end || v > max)
            return fmt::format("must be a decimal integer from 0 to {}, not '{}'", max,
                               text);
          text = std::to_string(v);
          return std::string();
        },
        "", "decimal");
  };
  constexpr std::uint64_t kMaxU64 = std::numeric_limits<std::uint64_t>::max();

  std::string check_path;
  CLI::App* check = app.add_subcommand(
      "check",
      "Validate a scene, experiment or lab dataset file and print what it holds");
  check
      ->add_option("FILE", check_path,
                   "scene, experiment or lab dataset (its dataset.json) JSON file")
      ->required();

  std::string table_path = "reference/paper/table1.json";
  CLI::App* reference = app.add_subcommand(
      "reference", "Check the paper's Table 1 against Eqs. 2, 3 and 6, side by side");
  reference->add_option("--table", table_path, "Table 1 as JSON")->capture_default_str();

  TrialArgs trial_args;
  CLI::App* trial = app.add_subcommand(
      "trial", "Run one seeded trial of a scene's assembling part and print its summary");
  trial->add_option("SCENE", trial_args.scene, "scene JSON file")->required();
  trial->footer(
      "Exit status: 0 the trial completed; 1 it ended otherwise (timeout, exhausted, "
      "unreachable, jammed, numerical_failure, step_budget): its summary is printed and "
      "its trace written, "
      "then 'vahf: trial ended STATUS: DETAIL' on stderr; 2 bad input, one line.");
  trial->add_option("--seed", trial_args.seed, "experiment seed (the stream key)")
      ->required()
      ->transform(decimal(kMaxU64));
  trial->add_option("--trial", trial_args.trial, "trial index (the stream key)")
      ->capture_default_str()
      ->transform(decimal(kMaxU64));
  trial
      ->add_option("--position", trial_args.position,
                   "which entry of the scene's sequence to assemble (0 = first)")
      ->capture_default_str();
  trial
      ->add_option("--integrator", trial_args.integrator,
                   "override simulation/integrator")
      ->check(CLI::IsMember(vahf::scene::StepperNames()));
  trial->add_option("--accuracy", trial_args.accuracy,
                    "override simulation/accuracy (its rule: `vahf params`)");
  trial
      ->add_option(
          "--set", trial_args.sets,
          "override a parameter, e.g. --set simulation/max_steps=20000 (repeatable; "
          "each by its rule in `vahf params`)")
      ->option_text("GROUP/KEY=VALUE");
  trial->add_option("--trace", trial_args.trace,
                    "write one CSV row per decision instant to this file");
  trial
      ->add_option(
          "--sample", trial_args.sample,
          "with --trace: also a row every DT s of simulated time (pose, velocities, "
          "forces, penetration), interpolated, so the trajectory is unchanged")
      ->option_text("DT");

  RunArgs run_args;
  CLI::App* run = app.add_subcommand(
      "run",
      "Run an experiment file and write its output directory (report.md, CSV "
      "tables, summary.json, manifest.json, plots)");
  run->add_option("EXPERIMENT", run_args.experiment, "experiment JSON file")->required();
  run->add_option("--seed", run_args.seed, "override the experiment's seed")
      ->transform(decimal(kMaxU64))
      ->each([&](const std::string&) { run_args.seed_given = true; });
  run->add_option("--trials", run_args.trials,
                  "override the cycles per condition (every experiment of a paper run)")
      ->transform(decimal(10'000'000))
      ->check(CLI::Range(1, 10'000'000));
  run->add_option("--threads", run_args.threads,
                  "worker threads (results do not depend on it)")
      ->transform(decimal(1024))
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();
  run->add_option(
      "--out", run_args.out,
      "output directory (default runs/NAME-seedSEED); replaced whole, only if it "
      "is empty or a previous vahf output");

  run->add_flag("--resume", run_args.resume,
                "continue the stopped run of the same command (Ctrl-C, kill, power "
                "loss) from the journal in its output's .partial folder: only what is "
                "missing runs, and the results are the same bits; with nothing "
                "journaled yet the run starts afresh; refused for a finished run or "
                "another run's journal (docs/reproducibility.md)");
  run->add_option("--overrides", run_args.overrides,
                  "parameter-override file (vahf-overrides/1, e.g. a calibration's "
                  "calibrated.json) applied to every scene the experiment runs");

  SynthesizeArgs synth_args;
  CLI::App* synthesize = app.add_subcommand(
      "synthesize",
      "Make a synthetic lab dataset: the model at stated parameter values plays "
      "the lab (docs/calibration.md)");
  synthesize
      ->add_option("GENERATOR", synth_args.generator,
                   "generator JSON file (vahf-synthetic/1)")
      ->required();
  synthesize
      ->add_option("--out", synth_args.out, "folder for dataset.json and trials.csv")
      ->required();
  synthesize
      ->add_option("--threads", synth_args.threads,
                   "worker threads (results do not depend on it)")
      ->transform(decimal(1024))
      ->check(CLI::Range(1, 1024))
      ->capture_default_str();

  vahf::kinds::VerifyOptions verify_options;
  CLI::App* verify = app.add_subcommand(
      "verify",
      "Re-run a run from its manifest.json and compare every result file "
      "(docs/reproducibility.md)");
  verify->add_option("RUN_DIR", verify_options.run_dir, "a run's output directory")
      ->required();
  verify
      ->add_option("--threads", verify_options.threads,
                   "worker threads of the re-run (default: the run's; results do not "
                   "depend on it)")
      ->transform(decimal(1024))
      ->check(CLI::Range(1, 1024));
  verify->add_option("--keep", verify_options.keep,
                     "keep the re-run's output directory here (default: a temporary "
                     "directory, removed)");
  verify->footer(
      "Run it from the directory the run was started in: inputs are found by the paths "
      "the manifest records. Exit status: 0 every result file identical; 1 one differs "
      "(the first named by file, row and column); 2 an unusable manifest, or an input "
      "missing or changed since the run (one line).");

  vahf::kinds::ReplayOptions replay_options;
  CLI::App* replay = app.add_subcommand("replay",
                                        "Run one cycle of a run again, alone, and "
                                        "compare its rows (docs/reproducibility.md)");
  replay->add_option("RUN_DIR", replay_options.run_dir, "a run's output directory")
      ->required();
  replay
      ->add_option("--cycle", replay_options.cycle,
                   "the cycle: a cycles table of the run and one of its data rows (1 = "
                   "the first), e.g. assembly_time_cycles.csv:12")
      ->option_text("TABLE:ROW")
      ->required();
  replay->add_option("--trace", replay_options.trace,
                     "write the cycle's trace (every part, a part column first) to this "
                     "CSV file");
  replay
      ->add_option("--sample", replay_options.sample,
                   "with --trace: also a row every DT s of simulated time, interpolated, "
                   "so the trajectory is unchanged")
      ->option_text("DT");
  replay->footer(
      "Run it from the directory the run was started in. Exit status: 0 the replayed "
      "rows are the table's, bit for bit; 1 one differs (named by row and column); 2 bad "
      "input (one line).");

  CLI::App* params = app.add_subcommand(
      "params", "Print every model parameter with its unit, rule and default (Markdown)");

  CLI::App* kind_index = app.add_subcommand(
      "kinds",
      "Print every experiment kind with its summary, keys, scenes and docs link "
      "(Markdown: docs/kinds.md)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    // One line, as every input error (CLI11's exit() adds a second).
    return fail(vahf::kExitInputError, "error", e.what(), "", true);
  }
  if (ranks && ranks->size() > 1 && !*run)
    return fail(vahf::kExitInputError, "error",
                vahf::InputError("mpirun", "", std::to_string(ranks->size()) + " ranks",
                                 "only `vahf run` spreads over MPI ranks: run the other "
                                 "commands alone")
                    .what(),
                "", true);

  try {
    if (*run) return Run(run_args, ranks.get());
    if (*check) return Check(check_path);
    if (*reference) return Reference(table_path);
    if (*trial) return Trial(trial_args);
    if (*synthesize) return Synthesize(synth_args);
    if (*replay) {
      vahf::experiment::InstallInterruptHandler();
      return vahf::kinds::Replay(replay_options);
    }
    if (*verify) {
      vahf::experiment::InstallInterruptHandler();
      return vahf::kinds::Verify(verify_options);
    }
    if (*params) {
      std::fputs(vahf::scene::ParameterTableMarkdown().c_str(), stdout);
      return 0;
    }
    if (*kind_index) {
      std::fputs(vahf::kinds::KindIndexMarkdown().c_str(), stdout);
      return 0;
    }
  } catch (const vahf::InputError& e) {
    return fail(vahf::kExitInputError, "error", e.what());
  } catch (const vahf::experiment::Interrupted& e) {
    return fail(vahf::kExitInterrupted, "interrupted", e.what(),
                "; no output was written");
  } catch (const vahf::ComputationError& e) {
    return fail(vahf::kExitComputationFailure, "error", e.what());
  } catch (const std::exception& e) {
    // Not one of ours: a library's exception or std::bad_alloc. The computation
    // failed all the same.
    return fail(vahf::kExitComputationFailure, "error", e.what());
  }
  return vahf::kExitComputationFailure;
}
