// A cycle assembles the sequence part after part, carrying time and work.
#include "vahf/experiment/cycle.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "vahf/scene/scene_loader.h"

namespace vahf::experiment {
namespace {

std::string Source(const std::string& relative) {
  const char* root = std::getenv("VAHF_SOURCE_DIR");
  return std::string(root ? root : VAHF_SOURCE_DIR) + "/" + relative;
}

TEST(Cycle, CarriesTimeAndWorkFromPartToPart) {
  const scene::Scene s =
      scene::LoadScene(Source("experiments/scenes/hydraulic_cylinder.json"));
  const CycleResult c = RunCycle(s, 1, 0, 100.0, false);
  ASSERT_TRUE(c.completed);
  ASSERT_EQ(c.parts.size(), s.sequence.size());
  double time = 0, work = 100.0;
  for (std::size_t p = 0; p < c.parts.size(); ++p) {
    const PartRun& part = c.parts[p];
    EXPECT_EQ(part.trial.part, s.parts[s.sequence[p]].name);
    EXPECT_EQ(part.trial.key.trial, 3 * 0 + p);  // CycleKey
    EXPECT_EQ(part.start_time, time);
    EXPECT_EQ(part.start_work, work);
    EXPECT_GT(part.trial.work, work);  // every part takes some work (Eq. 4)
    time += part.trial.end_time;
    work = part.trial.work;
  }
  EXPECT_EQ(c.time, time);
  EXPECT_EQ(c.work, work);
}

TEST(Cycle, AFailedPartEndsTheCycle) {
  scene::Scene s = scene::LoadScene(Source("experiments/scenes/hydraulic_cylinder.json"));
  s.params.simulation.time_limit = 0.05;  // no part can be placed in 50 ms
  const CycleResult c = RunCycle(s, 1, 0, 0.0, false);
  EXPECT_FALSE(c.completed);
  ASSERT_EQ(c.parts.size(), 1u);
  EXPECT_EQ(c.parts[0].trial.status, sim::Status::kTimeout);
  EXPECT_EQ(c.time, c.parts[0].trial.end_time);
}

TEST(Cycle, KeysNeverCollideAcrossCycles) {
  EXPECT_EQ(CycleKey(7, 0, 3, 2).trial, 2u);
  EXPECT_EQ(CycleKey(7, 1, 3, 0).trial, 3u);
  EXPECT_EQ(CycleKey(7, 1, 3, 0).seed, 7u);
}

}  // namespace
}  // namespace vahf::experiment
