// The experiment kinds, each registered once (kinds/kinds.def lists them; each
// defines its entry, `Kind XKind()`, in its own kinds/*_kind.cc): the keys of
// an experiment file it reads and how (each kind's reader, beside its input), what
// `vahf check` validates and says of it, and how `vahf run` runs, analyses and
// renders it. This is the top layer of the library: it sits above experiment/
// (designs of cycles), calibrate/, compare/ and report/, and the vahf command
// reaches every kind through it. A new kind is its line in kinds.def and its
// own files.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "vahf/experiment/design.h"
#include "vahf/report/output_directory.h"
#include "vahf/report/section.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::kinds {

struct Kind;

// What a run needs besides its experiment file.
struct RunContext {
  experiment::RunSettings settings;  // seed (resolved), trials override, threads
  report::OutputDirectory* directory = nullptr;  // created before any simulation
  // The kind run (RunExperiment sets it): a run of its own names its section
  // by it.
  const Kind* kind = nullptr;
};

struct Kind {
  std::string name;
  std::string summary;  // one line: what it runs and shows (docs/kinds.md)
  // Where the docs describe it, relative to docs/: its own page
  // "kinds/NAME.md", or the section of a page ("experiments.md#table1-...");
  // docs/kinds.md links it.
  std::string doc;
  // The keys of an experiment file it reads besides the common ones (format,
  // name, description, kind, seed, trials, scene); a key only other kinds read
  // is an error that names them.
  std::vector<std::string> keys;
  // Empty: the file names its scene in "scene". Otherwise the kind takes its
  // scenes elsewhere and this says where (the error for a "scene" key).
  std::string scene_elsewhere;
  // Reads the kind's keys into the file's input (after the header and scene).
  void (*parse)(const scene::JsonNode& root, const std::string& path,
                scene::ExperimentFile* e) = nullptr;
  // Validates what only loading or building can (lab datasets, trial models,
  // a paper run's experiments) before any simulation, and says what the file
  // holds, for `vahf check`; an InputError when something is wrong.
  std::string (*check)(const scene::ExperimentFile& file) = nullptr;
  // A design of cycles (a paper run lists only these): its run and its
  // analysis into a report section. Null for a kind with a run of its own.
  experiment::ExperimentRun (*design)(const scene::ExperimentFile& file,
                                      const experiment::RunSettings& settings) = nullptr;
  report::Section (*analyse)(const experiment::ExperimentRun& run) = nullptr;
  // A design's conditions as its cycles tables (KIND_*cycles.csv) name
  // them, for `vahf replay` (experiment/design.h); null: its cycles cannot be
  // replayed.
  std::vector<experiment::Condition> (*conditions)(
      const scene::ExperimentFile& file,
      const experiment::RunSettings& settings) = nullptr;
  // A run of experiments (a paper run): its own sections after its parts'
  // (which their kinds analyse), e.g. the handbooks beside the parts' times.
  std::vector<report::Section> (*sections_after_parts)(
      const experiment::ExperimentRun& run) = nullptr;
  // A run of experiments: the experiments it runs, in order (replay finds a
  // cycles table's experiment among them). Null: the file itself.
  std::vector<const scene::ExperimentFile*> (*parts)(const scene::ExperimentFile& file) =
      nullptr;
  // A run of its own (calibrate, compare): runs, writes the output directory,
  // prints what it found; returns the exit status. Null: a design's run.
  int (*run)(const scene::ExperimentFile& file, const RunContext& context) = nullptr;
  // Whether `trials` is the file's cycles per condition (`vahf check` says
  // so); false for a kind whose cycles are set otherwise (a paper run: each
  // listed experiment's; stability: each case's seeds).
  bool cycles_per_condition = true;
  // Its cycles time each part of the scene's sequence for operators as a lab
  // records them (assembly_time): a paper run's handbooks section reads the
  // first such experiment it lists.
  bool times_the_parts = false;
};

// Every kind, in the order of kinds.def (docs/kinds.md's).
const std::vector<Kind>& Kinds();
std::vector<std::string> KindNames();
// The kind named `name`; a program error when there is none (the file's kind
// was checked against KindNames when it was read).
const Kind& FindKind(const std::string& name);

// docs/kinds.md: every kind's name, summary, keys, scenes and docs link, as
// `vahf kinds` prints it.
std::string KindIndexMarkdown();

// Reads an experiment file: the common fields, the scene, then its kind's
// keys; errors name whichever file holds the fault.
scene::ExperimentFile LoadExperiment(const std::string& path);
// The same, then the parameter-override file `overrides` (vahf-overrides/1)
// applied to every scene it runs; empty: none (`vahf run --overrides`).
scene::ExperimentFile LoadExperiment(const std::string& path,
                                     const std::string& overrides);
// Where `vahf run` writes a run without --out: runs/NAME-seedSEED.
std::string DefaultRunDirectory(const scene::ExperimentFile& file, std::uint64_t seed);
scene::ExperimentFile ParseExperiment(const nlohmann::json& document,
                                      const std::string& path);

// `vahf check` of an experiment file: every validation a run makes before its
// first trial, and what the file holds.
std::string CheckExperiment(const scene::ExperimentFile& file);

// `vahf run`: validates as CheckExperiment does, runs the kind, writes the
// output directory and prints a summary; the exit status (1 when a plot could
// not be rendered: the results are kept).
int RunExperiment(const scene::ExperimentFile& file, const RunContext& context);

// A design's run (a paper run: each of its experiments', as parts) and its
// sections, one per experiment run, as the output directory holds them.
experiment::ExperimentRun RunDesign(const scene::ExperimentFile& file,
                                    const experiment::RunSettings& settings);
std::vector<report::Section> Sections(const experiment::ExperimentRun& run);

}  // namespace vahf::kinds
