// The manifest: the results digest follows its rule (checked against a value
// computed independently with Python's hashlib), changes with any byte of a
// result and not with fields outside the results (threads); the parameters
// object read back as a scene's "parameters" reproduces every value.
#include "vahf/report/manifest.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "vahf/report/digest.h"
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

}  // namespace
}  // namespace vahf::report
