// The Monte Carlo runner: results in index order and identical bits for 1, 2
// and 4 threads (docs/design.md, decision 9); the lowest-index exception wins whatever
// the scheduling; a stop request, by signal or test hook, ends the run with Interrupted;
// bad thread counts are rejected.
#include "vahf/experiment/runner.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <csignal>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/rng/stream.h"

namespace vahf::experiment {
namespace {

RunnerOptions Quiet(int threads) {
  RunnerOptions o;
  o.threads = threads;
  o.progress = false;
  return o;
}

// A deterministic value of trial i: a sum of Philox draws keyed by {seed, i}.
double TrialValue(std::size_t i) {
  rng::Stream s({2024, i}, 0, rng::Purpose::kTest);
  double sum = 0;
  for (int k = 0; k < 2000; ++k) sum += s.Normal() * s.Uniform();
  return sum;
}

class RunnerTest : public ::testing::Test {
 protected:
  void TearDown() override { ClearStopForTesting(); }
};

TEST_F(RunnerTest, SameBitsForOneTwoAndFourThreads) {
  const std::function<double(std::size_t)> fn = TrialValue;
  const std::vector<double> one = RunIndexed<double>(300, Quiet(1), fn);
  ASSERT_EQ(one.size(), 300u);
  for (std::size_t i = 0; i < one.size(); ++i) ASSERT_EQ(one[i], TrialValue(i)) << i;
  EXPECT_EQ(RunIndexed<double>(300, Quiet(2), fn), one);
  EXPECT_EQ(RunIndexed<double>(300, Quiet(4), fn), one);
}

TEST_F(RunnerTest, MoreThreadsThanTrialsAndNoTrials) {
  const std::function<std::size_t(std::size_t)> square = [](std::size_t i) {
    return i * i;
  };
  EXPECT_EQ(RunIndexed<std::size_t>(3, Quiet(8), square),
            (std::vector<std::size_t>{0, 1, 4}));
  EXPECT_TRUE(RunIndexed<std::size_t>(0, Quiet(2), square).empty());
}

TEST_F(RunnerTest, ResultsNeedNoDefaultConstructor) {
  struct Labelled {
    explicit Labelled(std::string t) : text(std::move(t)) {}
    std::string text;
  };
  const auto out = RunIndexed<Labelled>(
      5, Quiet(2), [](std::size_t i) { return Labelled("trial " + std::to_string(i)); });
  ASSERT_EQ(out.size(), 5u);
  EXPECT_EQ(out[4].text, "trial 4");
}

TEST_F(RunnerTest, LowestIndexExceptionWins) {
  // Index 30 throws at once; index 7 throws only after a delay, so with
  // several threads 30 fails first in time. 7 must still be the one reported.
  const std::function<int(std::size_t)> fn = [](std::size_t i) -> int {
    if (i == 7) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      throw std::runtime_error("trial 7 failed");
    }
    if (i == 30 || i == 31)
      throw std::runtime_error("trial " + std::to_string(i) + " failed");
    return static_cast<int>(i);
  };
  for (int threads : {1, 2, 4}) {
    try {
      RunIndexed<int>(100, Quiet(threads), fn);
      ADD_FAILURE() << "no exception with " << threads << " threads";
    } catch (const std::runtime_error& e) {
      EXPECT_STREQ(e.what(), "trial 7 failed") << threads << " threads";
    }
  }
}

TEST_F(RunnerTest, NoIndexAboveAFailureStartsAfterIt) {
  std::atomic<std::size_t> highest{0};
  const std::function<int(std::size_t)> fn = [&](std::size_t i) -> int {
    std::size_t seen = highest.load();
    while (i > seen && !highest.compare_exchange_weak(seen, i)) {
    }
    if (i == 3) throw std::logic_error("three");
    return 0;
  };
  EXPECT_THROW(RunIndexed<int>(1000, Quiet(1), fn), std::logic_error);
  EXPECT_EQ(highest.load(), 3u);
}

TEST_F(RunnerTest, StopRequestedBeforeTheRunStartsNothing) {
  RequestStopForTesting();
  std::atomic<int> calls{0};
  const std::function<int(std::size_t)> fn = [&](std::size_t) { return ++calls; };
  try {
    RunIndexed<int>(50, Quiet(2), fn);
    ADD_FAILURE() << "no Interrupted";
  } catch (const Interrupted& e) {
    EXPECT_STREQ(e.what(), "stopped on request after 0 of 50 trials");
  }
  EXPECT_EQ(calls.load(), 0);
}

TEST_F(RunnerTest, StopRequestedDuringTheRunLetsRunningTrialsFinish) {
  RunnerOptions options = Quiet(1);
  options.label = "fatigue";
  const std::function<int(std::size_t)> fn = [](std::size_t i) {
    if (i == 10) RequestStopForTesting();
    return static_cast<int>(i);
  };
  try {
    RunIndexed<int>(100, options, fn);
    ADD_FAILURE() << "no Interrupted";
  } catch (const Interrupted& e) {
    EXPECT_STREQ(e.what(), "fatigue: stopped on request after 11 of 100 trials");
  }
}

TEST_F(RunnerTest, AnErrorOutranksAStop) {
  const std::function<int(std::size_t)> fn = [](std::size_t i) -> int {
    if (i == 2) {
      RequestStopForTesting();
      throw std::runtime_error("two");
    }
    return 0;
  };
  EXPECT_THROW(RunIndexed<int>(10, Quiet(1), fn), std::runtime_error);
  ClearStopForTesting();
  EXPECT_THROW(RunIndexed<int>(10, Quiet(1), fn), std::runtime_error);
}

TEST_F(RunnerTest, SigintSetsTheStopFlag) {
  InstallInterruptHandler();
  EXPECT_FALSE(StopRequested());
  ASSERT_EQ(std::raise(SIGINT), 0);  // handled: the process goes on
  EXPECT_TRUE(StopRequested());
  // The handler was one-shot; re-arm it so SIGTERM is handled too.
  ClearStopForTesting();
  InstallInterruptHandler();
  ASSERT_EQ(std::raise(SIGTERM), 0);
  EXPECT_TRUE(StopRequested());
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
}

TEST_F(RunnerTest, ThreadsBelowOneIsAnError) {
  const std::function<int(std::size_t)> fn = [](std::size_t) { return 0; };
  for (int threads : {0, -3}) {
    try {
      RunIndexed<int>(5, Quiet(threads), fn);
      ADD_FAILURE() << "no exception for " << threads;
    } catch (const ComputationError& e) {
      EXPECT_EQ(e.reason(), ComputationError::Reason::kOutOfDomain);
      EXPECT_EQ(std::string(e.what()),
                "runner: threads = " + std::to_string(threads) + ": must be at least 1");
    }
  }
}

TEST_F(RunnerTest, AShortRunPrintsNoProgress) {
  std::FILE* stream = std::tmpfile();
  ASSERT_NE(stream, nullptr);
  RunnerOptions options = Quiet(2);
  options.progress = true;
  options.progress_stream = stream;
  RunIndexed<int>(20, options, [](std::size_t i) { return static_cast<int>(i); });
  EXPECT_EQ(std::ftell(stream), 0L);
  std::fclose(stream);
}

}  // namespace
}  // namespace vahf::experiment
