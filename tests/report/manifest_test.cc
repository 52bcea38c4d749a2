// The manifest: the results digest follows its rule (checked against a value
// computed independently with Python's hashlib), changes with any byte of a
// result and not with fields outside the results (threads); the parameters
// object read back as a scene's "parameters" reproduces every value; the
// manifest reads back as `vahf verify` reads it, and a manifest it cannot use
// is refused with the pointer and the rule; a manifest records the run of
// the same identity only (RecordsRun, for --resume).
#include "vahf/report/manifest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "vahf/core/digest.h"
#include "vahf/core/error.h"
#include "vahf/scene/parameter_table.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::report {
namespace {

const std::map<std::string, std::string> kResults = {
    {"summary.json", "{}"},
    {"a.csv", "x,y\n1,2\n"},
};

TEST(ResultsDigest, FollowsTheRule) {
  // python3 -c "import hashlib; print(hashlib.sha256(
  //   b'a.csv\x00x,y\n1,2\n\x00summary.json\x00{}\x00').hexdigest())"
  EXPECT_EQ(ResultsDigest(kResults),
            "5cdfcabc4050d0978593f1e732d2322238279980ec43b254a8975f4e85493b7d");
  EXPECT_EQ(ResultsDigest({}), Sha256Hex(""));
}

TEST(ResultsDigest, ChangesWithAnyByteOfAResult) {
  const std::string base = ResultsDigest(kResults);
  auto changed = kResults;
  changed["a.csv"][5] = '3';
  EXPECT_NE(ResultsDigest(changed), base);
  auto renamed = kResults;
  renamed["b.csv"] = renamed["a.csv"];
  renamed.erase("a.csv");
  EXPECT_NE(ResultsDigest(renamed), base);
  // The separators keep a byte from moving between name and content unseen.
  EXPECT_NE(ResultsDigest({{"ab", "c"}}), ResultsDigest({{"a", "bc"}}));
}

TEST(ResultsDigest, OfFilesEqualsOfBytesInAnyOrder) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "manifest_test_results";
  std::filesystem::create_directories(dir / "tables");
  std::map<std::string, std::string> files = kResults;
  files["tables/empty.csv"] = "";
  for (const auto& [name, bytes] : files)
    std::ofstream(dir / name, std::ios::binary) << bytes;
  EXPECT_EQ(
      ResultsDigestOfFiles(dir.string(), {"tables/empty.csv", "summary.json", "a.csv"}),
      ResultsDigest(files));
  std::filesystem::remove_all(dir);
}

ManifestFields Fields(int threads) {
  ManifestFields f;
  f.invocation = {"experiments/fatigue.json", "calibrated.json", 7, 0};
  f.experiment = {"experiments/fatigue.json", Sha256Hex("experiment")};
  f.scene = {"experiments/scenes/peg_in_hole.json", Sha256Hex("scene")};
  f.seed = 18446744073709551615u;  // 2^64 - 1 survives JSON
  f.trials = 500;
  f.threads = threads;
  f.result_files = {"a.csv", "summary.json"};
  f.results_digest = ResultsDigest(kResults);
  return f;
}

TEST(ManifestJson, HoldsEveryField) {
  const nlohmann::json m = ManifestJson(Fields(2));
  EXPECT_EQ(m["format"], "vahf-manifest/1");
  EXPECT_EQ(m["experiment"]["path"], "experiments/fatigue.json");
  EXPECT_EQ(m["invocation"], (nlohmann::json{{"experiment", "experiments/fatigue.json"},
                                             {"overrides", "calibrated.json"},
                                             {"seed", 7},
                                             {"trials", 0}}));
  EXPECT_EQ(m["scene"]["sha256"], Sha256Hex("scene"));
  EXPECT_EQ(m["seed"].get<std::uint64_t>(), 18446744073709551615u);
  EXPECT_EQ(m["trials"], 500);
  EXPECT_EQ(m["threads"], 2);
  EXPECT_EQ(m["parameters"]["guidance"]["kappa"], scene::Parameters{}.guidance.kappa);
  EXPECT_EQ(m["build"]["version"], GetBuildInfo().version);
  EXPECT_EQ(m["build"]["cxx_flags"], GetBuildInfo().cxx_flags);
  EXPECT_EQ(m["build"]["libraries"].size(), GetBuildInfo().libraries.size());
  for (const auto& [name, version] : GetBuildInfo().libraries)
    EXPECT_EQ(m["build"]["libraries"][name], version) << name;
  EXPECT_EQ(m["result_files"], (nlohmann::json{"a.csv", "summary.json"}));
  EXPECT_EQ(m["results_digest"], ResultsDigest(kResults));
  EXPECT_EQ(nlohmann::json::parse(m.dump(2)), m);
}

TEST(ManifestJson, ThreadCountDoesNotTouchTheResultsDigest) {
  const nlohmann::json one = ManifestJson(Fields(1));
  const nlohmann::json four = ManifestJson(Fields(4));
  EXPECT_NE(one, four);
  EXPECT_EQ(one["results_digest"], four["results_digest"]);
}

TEST(ParametersToJson, ReadsBackAsASceneSetsThem) {
  scene::Parameters p;
  p.guidance.kappa = 123.456789;
  p.contact.shell_spacing = 1.0 / 3.0 * 1e-3;
  p.visibility.mode = "constant";
  p.visibility.value = 0.75;
  p.visibility.grid = 17;
  p.simulation.integrator = "CPodes";
  const nlohmann::json params = ParametersToJson(p);
  EXPECT_EQ(params.size(), 9u);  // sight, glance, reach, fatigue, learning, guidance,
                                 // contact, visibility, simulation
  std::ifstream in(std::string(VAHF_SOURCE_DIR) + "/experiments/scenes/free_move.json");
  nlohmann::json scene_doc = nlohmann::json::parse(in);
  scene_doc["parameters"] = params;
  const scene::Scene s = scene::ParseScene(scene_doc, "free_move.json");
  std::size_t checked = 0;
  for (const scene::ParamSpec& spec : scene::ParameterTable()) {
    EXPECT_EQ(scene::ParamValueText(spec, s.params), scene::ParamValueText(spec, p))
        << spec.group << "/" << spec.key;
    EXPECT_TRUE(params[spec.group].contains(spec.key)) << spec.group << "/" << spec.key;
    ++checked;
  }
  EXPECT_EQ(checked, scene::ParameterTable().size());
}

// A manifest written to `dir`/manifest.json after `edit`, and its path.
template <class Edit>
std::string WrittenManifest(const std::string& dir, Edit edit) {
  const std::filesystem::path root = std::filesystem::path(::testing::TempDir()) / dir;
  std::filesystem::create_directories(root);
  nlohmann::json m = ManifestJson(Fields(3));
  m["inputs"] = {{{"path", "tables/table1.json"}, {"sha256", Sha256Hex("table")}}};
  edit(m);
  std::ofstream((root / "manifest.json").string()) << m.dump(1);
  return (root / "manifest.json").string();
}

TEST(ReadManifest, ReadsBackWhatManifestJsonWrote) {
  const std::string path = WrittenManifest("read_manifest_ok", [](nlohmann::json&) {});
  const RecordedRun r = ReadManifest(path);
  EXPECT_EQ(r.file, path);
  EXPECT_EQ(r.invocation.experiment, "experiments/fatigue.json");
  EXPECT_EQ(r.invocation.overrides, "calibrated.json");
  EXPECT_EQ(r.invocation.seed, 7u);
  EXPECT_EQ(r.invocation.trials, 0);
  EXPECT_EQ(r.threads, 3);
  ASSERT_EQ(r.inputs.size(), 3u);  // experiment, scene, then "inputs"
  EXPECT_EQ(r.inputs[0].file.path, "experiments/fatigue.json");
  EXPECT_EQ(r.inputs[0].pointer, "/experiment/sha256");
  EXPECT_EQ(r.inputs[1].file.sha256, Sha256Hex("scene"));
  EXPECT_EQ(r.inputs[2].file.path, "tables/table1.json");
  EXPECT_EQ(r.inputs[2].pointer, "/inputs/0/sha256");
  EXPECT_EQ(r.result_files, (std::vector<std::string>{"a.csv", "summary.json"}));
  EXPECT_EQ(r.results_digest, ResultsDigest(kResults));
  EXPECT_TRUE(BuildDifferences(r.build).empty());
}

// Each fault: the error names the manifest, the pointer and the rule.
TEST(ReadManifest, RefusesWhatVerifyCannotUse) {
  struct Case {
    const char* name;
    void (*edit)(nlohmann::json&);
    const char* where;
    const char* rule;
  };
  const Case cases[] = {
      {"format", [](nlohmann::json& m) { m["format"] = "vahf-experiment/1"; }, "/format",
       "not a vahf run's manifest"},
      {"no_invocation", [](nlohmann::json& m) { m.erase("invocation"); }, "/",
       "has no \"invocation\""},
      {"escaping_file", [](nlohmann::json& m) { m["result_files"][0] = "../a.csv"; },
       "/result_files/0", "inside the run directory"},
      {"absolute_file", [](nlohmann::json& m) { m["result_files"][1] = "/etc/passwd"; },
       "/result_files/1", "inside the run directory"},
      {"short_digest", [](nlohmann::json& m) { m["results_digest"] = "abc"; },
       "/results_digest", "64 lowercase hexadecimal"},
      {"input_digest", [](nlohmann::json& m) { m["inputs"][0]["sha256"] = 5; },
       "/inputs/0/sha256", "string"},
      {"negative_trials", [](nlohmann::json& m) { m["invocation"]["trials"] = -1; },
       "/invocation/trials", ""},
  };
  for (const Case& c : cases) {
    const std::string path =
        WrittenManifest(std::string("read_manifest_") + c.name, c.edit);
    try {
      ReadManifest(path);
      ADD_FAILURE() << c.name << ": accepted";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), path) << c.name;
      EXPECT_EQ(e.where(), c.where) << c.name;
      EXPECT_NE(e.rule().find(c.rule), std::string::npos) << c.name << ": " << e.what();
    }
  }
}

// A finished run's manifest records the run whose RunIdentity (of the same
// files, read back) has its invocation, build and input digests; any one
// of them different, or JSON that is not a manifest, does not.
TEST(RecordsRun, MatchesTheSameRunOnly) {
  const std::filesystem::path dir =
      std::filesystem::path(::testing::TempDir()) / "records_run_test";
  std::filesystem::create_directories(dir);
  const std::string experiment = (dir / "e.json").string();
  const std::string scene = (dir / "s.json").string();
  const std::string table = (dir / "t.csv").string();
  std::ofstream(experiment) << "experiment";
  std::ofstream(scene) << "scene";
  std::ofstream(table) << "table";
  ManifestFields f = Fields(1);
  f.invocation = {experiment, "", 7, 0};
  f.experiment = DescribeInputFile(experiment);
  f.scene = DescribeInputFile(scene);
  nlohmann::json manifest = ManifestJson(f);
  manifest["inputs"] = {{{"path", table}, {"sha256", Sha256Hex("table")}}};
  const nlohmann::json identity = RunIdentity(f.invocation, {experiment, scene, table});
  EXPECT_TRUE(RecordsRun(manifest, identity));
  EXPECT_TRUE(RecordsRun(manifest, RunIdentity(f.invocation, {experiment})));

  EXPECT_FALSE(RecordsRun(manifest, RunIdentity({experiment, "", 8, 0}, {experiment})));
  EXPECT_FALSE(RecordsRun(manifest, RunIdentity({experiment, "", 7, 3}, {experiment})));
  nlohmann::json other_build = manifest;
  other_build["build"]["compiler_version"] = "99.1";
  EXPECT_FALSE(RecordsRun(other_build, identity));
  std::ofstream(table) << "table, edited";
  EXPECT_FALSE(RecordsRun(manifest, RunIdentity(f.invocation, {experiment, table})));
  std::ofstream(scene) << "scene, edited";
  EXPECT_FALSE(RecordsRun(manifest, RunIdentity(f.invocation, {scene})));
  EXPECT_FALSE(RecordsRun(nlohmann::json::array(), identity));
  EXPECT_FALSE(RecordsRun(nlohmann::json{{"invocation", 1}}, identity));
  std::filesystem::remove_all(dir);
}

TEST(BuildDifferences, NamesEachFieldAndLibraryThatDiffers) {
  BuildInfo other = GetBuildInfo();
  const nlohmann::json mine = ManifestJson(Fields(1))["build"];
  EXPECT_TRUE(BuildDifferences(mine, other).empty());
  other.compiler_version = "99.1";
  other.libraries.emplace_back("HDF5", "1.10");  // a library the run lacked
  const std::vector<std::string> d = BuildDifferences(mine, other);
  ASSERT_EQ(d.size(), 2u);
  EXPECT_EQ(d[0], "compiler_version: " + GetBuildInfo().compiler_version +
                      " (run) vs 99.1 (this program)");
  EXPECT_EQ(d[1], "libraries/HDF5: (none) (run) vs 1.10 (this program)");
}

}  // namespace
}  // namespace vahf::report
