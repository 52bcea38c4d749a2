// The paper's claims, tested statistically on seeded runs of the
// shipped experiments at a reduced size. Each run is deterministic, so these
// tests never flake; they fail when the model's behaviour changes. Where the
// model with defensible parameters does not reproduce a claim, the test
// records that and checks what the model does instead (docs/experiments.md).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "vahf/experiment/design.h"
#include "vahf/kinds/kind.h"
#include "vahf/report/output_directory.h"
#include "vahf/report/run_output.h"
#include "vahf/report/section.h"
#include "vahf/scene/experiment_file.h"

namespace vahf::report {
namespace {

std::string Source(const std::string& relative) {
  const char* root = std::getenv("VAHF_SOURCE_DIR");
  return std::string(root ? root : VAHF_SOURCE_DIR) + "/" + relative;
}

struct Ran {
  scene::ExperimentFile file;
  experiment::ExperimentRun run;
  Section section;
};

// Runs experiments/NAME.json with `trials` cycles per condition. The file
// lives as long as the run that points at it.
std::unique_ptr<Ran> RunShipped(const std::string& name, int trials) {
  auto r = std::make_unique<Ran>();
  r->file = kinds::LoadExperiment(Source("experiments/" + name + ".json"));
  experiment::RunSettings s;
  s.seed = r->file.seed;
  s.trials = trials;
  s.progress = false;
  r->run = kinds::RunDesign(r->file, s);
  r->section = kinds::Sections(r->run).front();
  return r;
}

[[maybe_unused]] const nlohmann::json& ClaimContaining(const Section& s,
                                                       const std::string& text) {
  for (const auto& c : s.summary.at("claims"))
    if (c.at("claim").get<std::string>().find(text) != std::string::npos) return c;
  ADD_FAILURE() << "no claim containing '" << text << "' in " << s.summary.dump(1);
  static const nlohmann::json none = {{"reproduced", false}, {"evidence", ""}};
  return none;
}

// Table 1, Sec. 4: eta rises as each part nears its final position.
// Reproduced for the piston rod and the guide sleeve. The seal ring's rise is
// not significant at this size since the guidance became continuous in the
// state: eta(d) - eta(a) = 0.038, 95 % CI [-0.027, 0.103] over 4
// cycles (measured); it stays positive, and the paper run's size tests it.
TEST(PaperClaims, EtaRisesAsEachPartNearsItsTarget) {
  const auto r = RunShipped("table1", 4);
  const auto& claims = r->section.summary.at("claims");
  ASSERT_EQ(claims.size(), 3u);
  for (const auto& c : claims) {
    const std::string claim = c.at("claim").get<std::string>();
    std::printf("%s: %s\n", claim.c_str(), c.at("evidence").get<std::string>().c_str());
    if (claim.find("seal_ring") == std::string::npos)
      EXPECT_TRUE(c.at("reproduced").get<bool>()) << c.dump();
    else
      EXPECT_NE(c.at("evidence").get<std::string>().find("eta(d) - eta(a) = 0.0"),
                std::string::npos)
          << "the seal ring's rise is small and positive: " << c.dump();
  }
}

// Numerical health of the same run: no numerical failure, no part deeper
// than its bound (the resolved fits: no penetration_bound warning), and no
// warning but the two the resolved piston rod is known for (docs/physics.md,
// Integrators): at its first strike on the barrel's mouth, about 0.11 s in,
// the barrier stops it within the bound with accepted steps below 1e-8 s
// (step_size_floor), and CVODE recovers from Newton failures there
// (integrator_retry). And rests (`rest`): the rod rests at the mouth under
// the regularised friction, creeping below its transition speed (issue 53,
// docs/physics.md "Rests"); not numerical trouble, a measure of the model.
TEST(PaperClaims, Table1RunHasOnlyTheExpectedWarnings) {
  const auto r = RunShipped("table1", 4);
  const nlohmann::json& health = r->section.summary.at("health");
  for (const auto& c : health.at("conditions")) {
    EXPECT_EQ(c.at("numerical_failures"), 0) << c.dump();
    for (const auto& [kind, w] : c.at("warnings").items())
      EXPECT_TRUE(kind == "step_size_floor" || kind == "integrator_retry" ||
                  kind == "rest")
          << "unexpected warning " << kind << ": " << w.dump();
  }
  EXPECT_NE(r->section.markdown.find("### Numerical health"), std::string::npos);
}

// Sec. 5.2, one run for both claims.
// (1) The three male operators assemble faster than the three female ones.
// NOT reproduced: in the model sex acts only through stature and arm length
// (posture, so f, r, g), and at this size the difference is not significant.
// What the model does instead: the male - female difference is small (under
// 0.5 s) and not significant.
// (2) Fig. 12: subassembly time falls with the part's mass and size.
// Reproduced with the resolved, oiled fits: the piston rod (3.6 kg) is
// significantly slower than the guide sleeve (0.8 kg), and the sleeve than the
// seal ring (25 g), whose 119 um fit the oil and the wrist let it enter at
// once (measured at this size: rod - sleeve 0.56 s, sleeve - ring 0.76 s,
// both p < 1e-6). Under the point-shell contact the ring was not faster than
// the sleeve (sleeve - ring -0.06 s, p = 0.99): half reproduced.
TEST(PaperClaims, AssemblyTimeSexNotReproducedMassReproduced) {
  const auto r = RunShipped("assembly_time", 4);
  const nlohmann::json& claim = ClaimContaining(r->section, "male operators");
  EXPECT_FALSE(claim.at("reproduced").get<bool>()) << claim.dump();
  const nlohmann::json& t = r->section.summary.at("tests").at("male_vs_female");
  EXPECT_GT(t.at("p_less").get<double>(), 0.05) << t.dump();
  EXPECT_LT(std::abs(t.at("mean_difference_s").get<double>()), 0.5) << t.dump();
  const nlohmann::json& mass = ClaimContaining(r->section, "subassembly time");
  EXPECT_TRUE(mass.at("reproduced").get<bool>()) << mass.dump();
  const nlohmann::json& steps = r->section.summary.at("tests").at("heavier_vs_lighter");
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_EQ(steps[0].at("heavier"), "piston_rod");
  EXPECT_EQ(steps[1].at("lighter"), "seal_ring");
  for (const auto& step : steps) {
    EXPECT_GT(step.at("mean_difference_s").get<double>(), 0.0) << steps.dump();
    EXPECT_LT(step.at("p_heavier_slower").get<double>(), 0.05) << steps.dump();
  }
}

// Sec. 5.3: the general condition lies between the best and the worst. Half
// reproduced: the worst condition (standing far, part screened) gives
// significantly larger eta and lambda_c than the general one, but standing
// close does not make the model's operator better off: looking steeply down
// into the barrel, the part is hidden sooner, and eta is if anything larger.
// Six cycles a condition: with the resolved, oiled fits the worst condition's
// eta rise is 0.147 over the general one, p = 0.019 at this size, but p =
// 0.068 at four cycles (measured); lambda_c's 0.41, p = 1e-4.
TEST(PaperClaims, WorkingConditionsWorstReproducedBestNot) {
  const auto r = RunShipped("human_factors_groups", 6);
  for (const char* q : {"eta", "lambda_c"}) {
    const nlohmann::json& claim =
        ClaimContaining(r->section, std::string(q) + " of the general condition");
    EXPECT_FALSE(claim.at("reproduced").get<bool>()) << claim.dump();
    const nlohmann::json& t = r->section.summary.at("tests").at(q);
    std::printf("%s: %s\n", q, t.dump().c_str());
    EXPECT_LT(t.at("p_general_below_worst").get<double>(), 0.05) << q << t.dump();
    EXPECT_GT(t.at("p_best_below_general").get<double>(), 0.05) << q << t.dump();
  }
}

// Sec. 5.4: over an hour the mean time rises and the success rate falls
// (paper: 0.96 to 0.75). The rate does not fall: Eq. 4's work over an hour of
// cycles is some hundreds of kJ against A_max = 1600 kcal = 6.69 MJ (Eq. 6),
// so Psi_c stays near 0.95 and every cycle of the first and last segments
// succeeds. The time rises, a little: the operator's force is 5 % weaker at
// the end of the hour, and the same cycles, paired by their streams, take
// longer. Whether that is significant depends on the size (measured: +0.046 s,
// paired p = 0.019 here with 4 cycles; +0.029 s, p = 0.079, "no", in the
// paper run's 12), so this test asserts the direction, not the verdict.
TEST(PaperClaims, FatigueTimeRisesALittleButTheSuccessRateDoesNotFall) {
  const auto r = RunShipped("fatigue", 4);
  const nlohmann::json& s = r->section.summary;
  const nlohmann::json& rate = ClaimContaining(r->section, "success rate falls");
  EXPECT_EQ(rate.at("verdict"), "no") << rate.dump();
  const nlohmann::json& time = ClaimContaining(r->section, "mean assembly time rises");
  std::printf("%s\n", time.at("evidence").get<std::string>().c_str());
  EXPECT_NE(time.at("verdict"), "untestable") << time.dump();
  // Measured: 0.949 here (4-cycle pilot, 95 J/s), 0.954 in the paper run.
  // Bound: an hour at up to 185 J/s, twice the measured rate, keeps Psi_c
  // above 0.9.
  EXPECT_GT(s.at("psi_end_of_hour").get<double>(), 0.9) << s.dump();
  EXPECT_LT(s.at("psi_end_of_hour").get<double>(), 1.0) << s.dump();
  const nlohmann::json& t = s.at("tests");
  EXPECT_EQ(t.at("success_last").at("successes"), t.at("success_last").at("cycles"));
  EXPECT_EQ(t.at("pairs_succeeded_then_failed"), 0) << t.dump();
  const nlohmann::json& rise = t.at("time_last_minus_first");
  EXPECT_EQ(rise.at("pairs"), 4) << rise.dump();
  // "A little": the model's slowing by Psi_c 0.95 is within the noise of 4
  // pairs (measured -0.031 s, 95 % CI [-0.31, 0.25], p = 0.63), so its sign
  // is not asserted: the pairs' mean stays under a tenth of the 7.9 s cycle
  // (paper.json) and their interval admits a rise.
  EXPECT_LT(std::abs(rise.at("mean_difference_s").get<double>()), 0.79) << rise.dump();
  EXPECT_GT(rise.at("ci_upper_s").get<double>(), 0.0) << rise.dump();
}

// Every kind's report renders: tables, summary, and each gnuplot figure; and
// each writes what its trials cost (report/cost.h) as a measured file, a row
// per part with the CPU its trials took.
TEST(PaperClaims, EveryKindWritesItsReportWithAllPlots) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "vahf_paper_claims_report";
  std::filesystem::remove_all(dir);
  for (const char* name :
       {"table1", "assembly_time", "human_factors_groups", "fatigue"}) {
    const auto r = RunShipped(name, 1);
    OutputDirectory out((dir / name).string());
    const RunOutput written = WriteRunOutput(r->run, {r->section}, out, RunInfo{});
    EXPECT_TRUE(written.failed_plots.empty()) << name << ": " << written.failed_plots[0];
    for (const Plot& p : r->section.plots)
      EXPECT_TRUE(std::filesystem::exists(dir / name / p.file)) << p.file;
    EXPECT_TRUE(std::filesystem::exists(dir / name / "report.md"));
    const std::string cost = std::string(name) + "_cost.csv";
    std::ifstream manifest_file(dir / name / "manifest.json");
    const nlohmann::json manifest = nlohmann::json::parse(manifest_file);
    EXPECT_EQ(manifest.at("measured_files"), (nlohmann::json{cost, "measured.json"}));
    const nlohmann::json& parts = r->section.measured.at("cost").at("parts");
    ASSERT_EQ(parts.size(), 3u) << name;  // the cylinder's three parts
    EXPECT_EQ(parts[0].at("part"), "piston_rod");
    EXPECT_GT(parts[0].at("cpu_p50_s").get<double>(), 0.0);
    EXPECT_GE(parts[0].at("cpu_max_s").get<double>(),
              parts[0].at("cpu_p50_s").get<double>());
  }
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace vahf::report
