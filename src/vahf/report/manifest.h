// The manifest of a run (docs/outputs.md): everything needed to re-run it -
// input files and their digests, seed, trial count, every model parameter,
// what built the program - and one digest of the results, which two runs of
// the same inputs must share whatever their thread count or wall time.
#pragma once

#include <cstdint>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "vahf/report/build_info.h"
#include "vahf/scene/parameters.h"

namespace vahf::report {

inline constexpr const char* kManifestFormat = "vahf-manifest/1";

// An input file as the user named it, and the SHA-256 of its bytes.
struct InputFile {
  std::string path;
  std::string sha256;
};
// Reads and digests `path` (an InputError if unreadable).
InputFile DescribeInputFile(const std::string& path);

// Every model parameter as group -> key -> value, with the groups and keys of
// a scene file's "parameters" object (scene/parameter_table.h): a scene that
// sets this object reproduces `p` exactly. Numbers are JSON numbers (doubles
// round-trip), choices strings.
nlohmann::json ParametersToJson(const scene::Parameters& p);

// The results digest: SHA-256 over the files in name order (std::string
// order of the names), each contributing its name, a NUL byte, its bytes and
// a NUL byte. Only result files enter it (CSV tables, summary.json): never
// the manifest, wall times, or plots whose bytes depend on the renderer.
std::string ResultsDigest(const std::map<std::string, std::string>& files);
// The same over files read from `root`/name (InputError if one is unreadable).
std::string ResultsDigestOfFiles(const std::string& root,
                                 const std::vector<std::string>& names);

// How the run was started, so that `vahf verify` can start it again: the
// experiment file and override file as named on the command line (empty: no
// --overrides), the seed it ran with and the --trials given (0: the file's).
struct Invocation {
  std::string experiment;
  std::string overrides;
  std::uint64_t seed = 0;
  std::int64_t trials = 0;
};

struct ManifestFields {
  Invocation invocation;
  InputFile experiment;
  InputFile scene;
  std::uint64_t seed = 0;
  std::int64_t trials = 0;
  int threads = 1;
  int ranks = 1;  // MPI ranks (experiment/ranks.h); results do not depend on it
  scene::Parameters parameters;  // the scene's, after its overrides
  BuildInfo build = GetBuildInfo();
  std::vector<std::string> result_files;  // the names ResultsDigest covered
  std::string results_digest;
};

// {"format": "vahf-manifest/1", "invocation": {"experiment", "overrides",
// "seed", "trials"}, "experiment": {"path", "sha256"}, "scene": {...},
// "seed", "trials", "threads", "ranks", "parameters": ParametersToJson,
// "build": {"version", "git_describe", "compiler", "compiler_version",
// "build_type", "cxx_flags"}, "result_files": [...], "results_digest"}.
// Keys are sorted, so dump() is deterministic.
nlohmann::json ManifestJson(const ManifestFields& fields);

// What a run's journal must find equal to resume it (experiment/journal.h):
// the invocation, the SHA-256 of each file the experiment names before it
// runs (the experiment, the override file, its scene, and the files its kind
// lists: conditions' scenes, a paper table, a paper run's experiments) and
// the build. Files found only while running (a lab dataset's tables) are
// not in it; `vahf verify` checks those afterwards.
nlohmann::json RunIdentity(const Invocation& invocation,
                           const std::vector<std::string>& files);

// Whether `manifest` (a finished run's manifest.json, as parsed) records the
// run `identity` (RunIdentity) describes: the same invocation and build, and
// the same SHA-256 for every input both name. False for anything else,
// including JSON that is not a manifest.
bool RecordsRun(const nlohmann::json& manifest, const nlohmann::json& identity);

// A manifest as `vahf verify` reads it back.
struct RecordedRun {
  std::string file;  // the manifest's path, for messages
  Invocation invocation;
  int threads = 1;
  int ranks = 1;  // "ranks", absent (1) in manifests written before MPI
  // Every input with its digest and the JSON pointer of its "sha256": the
  // experiment, the scene, then "inputs" in order.
  struct Input {
    InputFile file;
    std::string pointer;
  };
  std::vector<Input> inputs;
  nlohmann::json build;  // as written: compared with this program's
  std::vector<std::string> result_files;
  std::string results_digest;
};

// Reads `path` (a run's manifest.json). An InputError names the file, the
// pointer, the value and the rule for anything verify cannot use: another
// format, a missing field, a result file that is not a plain relative path,
// a digest that is not 64 hexadecimal digits, and a manifest written before
// "invocation" existed.
RecordedRun ReadManifest(const std::string& path);

// The fields of this program's build that differ from `recorded` (a
// manifest's "build"), each as "NAME: RECORDED (run) vs THIS (this
// program)"; empty when the build is the same.
std::vector<std::string> BuildDifferences(const nlohmann::json& recorded,
                                          const BuildInfo& build = GetBuildInfo());

}  // namespace vahf::report
