// Pooled within-operator variances (calibrate/targets.h, PoolVariances): in
// closed form, and on the bundled synthetic lab's operators.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "vahf/calibrate/targets.h"
#include "vahf/data/lab_dataset.h"
#include "vahf/scene/scene_loader.h"

namespace vahf::calibrate {
namespace {

std::string Path(const std::string& relative) {
  return std::string(VAHF_SOURCE_DIR) + "/" + relative;
}

Target Of(const std::string& pointer, bool pooled) {
  Target t;
  t.spec.quantity = "assembly_time";
  t.spec.by_operator = true;
  t.spec.pointer = pointer;
  t.spec.pooled_variance = pooled;
  return t;
}

Statistic Mean(int n, double variance) {
  Statistic s;
  s.value = 1.0;
  s.n = n;
  s.variance = variance;
  return s;
}

// Operators of 4 and 6 times with s^2 = 4 and 3 give (3 * 4 + 5 * 3) / 8 =
// 27 / 8; one of 2 times without a variance adds nothing and takes 27 / 16.
// A target of another spec, and a single draw of the pooled one, keep theirs.
TEST(PooledVariance, IsTheWithinOperatorMeanSquareOverEachOperatorsCount) {
  const std::vector<Target> targets = {Of("/targets/0", true), Of("/targets/0", true),
                                       Of("/targets/0", true), Of("/targets/0", true),
                                       Of("/targets/1", false)};
  Statistic draw = Mean(1, std::nan(""));
  draw.single_draw = true;
  std::vector<Statistic> stats = {Mean(4, 1.0), Mean(6, 0.5), Mean(2, std::nan("")), draw,
                                  Mean(5, 0.7)};
  PoolVariances(targets, &stats);
  const double pooled = 27.0 / 8.0;
  EXPECT_DOUBLE_EQ(stats[0].variance, pooled / 4);
  EXPECT_DOUBLE_EQ(stats[1].variance, pooled / 6);
  EXPECT_DOUBLE_EQ(stats[2].variance, pooled / 2);
  EXPECT_TRUE(std::isnan(stats[3].variance));
  EXPECT_DOUBLE_EQ(stats[4].variance, 0.7);
  EXPECT_DOUBLE_EQ(stats[0].value, 1.0);  // only variances move
}

// Two specs of the same quantity pool apart: each over its own operators.
TEST(PooledVariance, PoolsEachSpecApart) {
  const std::vector<Target> targets = {Of("/targets/0", true), Of("/targets/0", true),
                                       Of("/targets/1", true), Of("/targets/1", true)};
  std::vector<Statistic> stats = {Mean(3, 1.0), Mean(3, 3.0), Mean(5, 0.2), Mean(5, 0.2)};
  PoolVariances(targets, &stats);
  EXPECT_DOUBLE_EQ(stats[0].variance, 2.0);  // (2 * 3 + 2 * 9) / 4 / 3
  EXPECT_DOUBLE_EQ(stats[1].variance, 2.0);
  EXPECT_DOUBLE_EQ(stats[2].variance, 0.2);
  EXPECT_DOUBLE_EQ(stats[3].variance, 0.2);
}

// On data/synthetic_block (six operators, ten times each), a pooled target's
// lab variances are one s_p^2 over each operator's count, s_p^2 the mean of
// the operators' own s_o^2 (equal counts); the means are the operators' own.
TEST(PooledVariance, LabTargetsOfTheSyntheticBlockShareOneVariance) {
  const scene::Scene scene =
      scene::LoadScene(Path("experiments/scenes/steel_block_move.json"));
  const data::LabDataset lab =
      data::LoadLabDataset(Path("data/synthetic_block/dataset.json"));
  TargetSpec spec;
  spec.quantity = "assembly_time";
  spec.part = "block";
  spec.by_operator = true;
  spec.pointer = "/targets/0";
  const std::vector<Target> own = LabTargets(scene, lab, {spec}, "test.json");
  spec.pooled_variance = true;
  const std::vector<Target> pooled = LabTargets(scene, lab, {spec}, "test.json");
  ASSERT_EQ(own.size(), 6u);
  ASSERT_EQ(pooled.size(), own.size());
  double sum = 0;
  for (const Target& t : own) sum += t.lab.variance * t.lab.n;
  const double s2 = sum / static_cast<double>(own.size());
  bool differ = false;
  for (std::size_t i = 0; i < own.size(); ++i) {
    EXPECT_EQ(pooled[i].lab.n, 10);
    EXPECT_DOUBLE_EQ(pooled[i].lab.value, own[i].lab.value);
    EXPECT_NEAR(pooled[i].lab.variance, s2 / own[i].lab.n, 1e-15);
    differ = differ || std::abs(own[i].lab.variance / pooled[i].lab.variance - 1) > 0.1;
  }
  EXPECT_TRUE(differ) << "the operators' own variances should differ";
}

}  // namespace
}  // namespace vahf::calibrate
