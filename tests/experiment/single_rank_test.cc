// The launch of a build without MPI (experiment/single_rank.cc), compiled
// into this test in every build, so that the path a machine without Open
// MPI takes is tested where MPI is found too: a process started alone, or
// as a job of one, runs alone; one launched among several is refused with
// an error naming the launcher's variable.
#include <gtest/gtest.h>

#include <array>
#include <cstdlib>
#include <optional>
#include <string>

#include "vahf/core/error.h"
#include "vahf/experiment/launched_ranks.h"

namespace vahf::experiment {
namespace {

constexpr std::array<const char*, 3> kLauncherVariables = {"OMPI_COMM_WORLD_SIZE",
                                                           "PMIX_RANK", "PMI_SIZE"};

// Each test starts with no launcher variable set; the ones the process had
// are restored after it.
class SingleRankTest : public ::testing::Test {
 protected:
  void SetUp() override {
    for (std::size_t i = 0; i < kLauncherVariables.size(); ++i) {
      if (const char* v = std::getenv(kLauncherVariables[i])) saved_[i] = v;
      unsetenv(kLauncherVariables[i]);
    }
  }
  void TearDown() override {
    for (std::size_t i = 0; i < kLauncherVariables.size(); ++i) {
      unsetenv(kLauncherVariables[i]);
      if (saved_[i]) setenv(kLauncherVariables[i], saved_[i]->c_str(), 1);
    }
  }

 private:
  std::array<std::optional<std::string>, 3> saved_;
};

TEST_F(SingleRankTest, AProcessStartedAloneRunsAlone) {
  EXPECT_EQ(LauncherVariable(), "");
  EXPECT_EQ(JoinLaunchedRanks(nullptr, nullptr), nullptr);
}

TEST_F(SingleRankTest, AJobOfOneProcessRunsAlone) {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    setenv(name, "1", 1);
    EXPECT_EQ(JoinLaunchedRanks(nullptr, nullptr), nullptr) << name;
    unsetenv(name);
  }
}

TEST_F(SingleRankTest, AProcessLaunchedAmongSeveralIsRefused) {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"}) {
    setenv(name, "3", 1);
    try {
      JoinLaunchedRanks(nullptr, nullptr);
      ADD_FAILURE() << name << "=3 ran alone";
    } catch (const InputError& e) {
      EXPECT_EQ(e.file(), "environment");
      EXPECT_EQ(e.value(), std::string(name) + "=3");
      EXPECT_NE(e.rule().find("built without MPI"), std::string::npos) << e.rule();
    }
    unsetenv(name);
  }
}

}  // namespace
}  // namespace vahf::experiment
