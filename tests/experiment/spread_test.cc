// RunIndexed spread over ranks (runner.h, ranks.h), with threads standing in
// for MPI's processes: every rank count and thread count gives every rank the
// one-process results, each index run once; the lowest failing index's
// error, with its class and fields, is thrown on every rank; a stop on any
// rank stops all; rank 0's journal is read and completed with every rank's
// results, so a resume on another rank count runs only what is missing, and
// its refusal stops every rank. Errors travel between ranks as bytes and come back as
// they went.
#include <gtest/gtest.h>

#include <atomic>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/experiment/journal.h"
#include "vahf/experiment/ranks.h"
#include "vahf/experiment/runner.h"

namespace vahf::experiment {
namespace {
namespace fs = std::filesystem;

// K threads as the K ranks of a job: AllGather meets when all have called.
class ThreadGroup {
 public:
  explicit ThreadGroup(int size) : size_(size), slots_(static_cast<std::size_t>(size)) {}
  std::vector<std::string> AllGather(int rank, const std::string& mine) {
    std::unique_lock<std::mutex> lock(mutex_);
    const std::uint64_t round = round_;
    slots_[static_cast<std::size_t>(rank)] = mine;
    if (++arrived_ == size_) {
      gathered_ = slots_;
      arrived_ = 0;
      ++round_;
      met_.notify_all();
    } else {
      met_.wait(lock, [&] { return round_ != round; });
    }
    ++gathers_;
    return gathered_;
  }
  int size() const { return size_; }
  int gathers() const { return gathers_; }

 private:
  int size_;
  std::mutex mutex_;
  std::condition_variable met_;
  std::vector<std::string> slots_, gathered_;
  int arrived_ = 0;
  int gathers_ = 0;
  std::uint64_t round_ = 0;
};

class ThreadRank : public Ranks {
 public:
  ThreadRank(ThreadGroup* group, int rank) : group_(group), rank_(rank) {}
  int rank() const override { return rank_; }
  int size() const override { return group_->size(); }
  std::vector<std::string> AllGather(const std::string& mine) const override {
    return group_->AllGather(rank_, mine);
  }
  [[noreturn]] void Abort(int status) const override {
    std::fprintf(stderr, "rank %d aborted the job with %d\n", rank_, status);
    std::abort();  // the protocol never needs it: a test that gets here fails
  }

 private:
  ThreadGroup* group_;
  int rank_;
};

std::string EncodeDouble(const double& x) {
  std::string s(sizeof x, '\0');
  std::memcpy(s.data(), &x, sizeof x);
  return s;
}
double DecodeDouble(const std::string& s) {
  double x = 0;
  std::memcpy(&x, s.data(), sizeof x);
  return x;
}
constexpr ResultCodec<double> kDoubleCodec{EncodeDouble, DecodeDouble};

double Value(std::size_t i) { return 1.0 / (static_cast<double>(i) + 3.0); }

// What each rank got: its results, or the exception it threw.
struct Outcome {
  std::vector<double> results;
  std::exception_ptr error;
};

// Runs RunIndexed(n, fn) on `size` ranks of `threads` threads each;
// `journal` (may be null) is rank 0's.
std::vector<Outcome> RunOnRanks(int size, int threads, std::size_t n,
                                const std::function<double(std::size_t)>& fn,
                                Journal* journal = nullptr) {
  ThreadGroup group(size);
  std::vector<Outcome> out(static_cast<std::size_t>(size));
  std::vector<std::thread> ranks;
  for (int r = 0; r < size; ++r)
    ranks.emplace_back([&, r] {
      const ThreadRank rank(&group, r);
      RunnerOptions options;
      options.threads = threads;
      options.progress = false;
      options.ranks = &rank;
      if (r == 0) options.journal = journal;
      Outcome& o = out[static_cast<std::size_t>(r)];
      try {
        o.results = RunIndexed<double>(n, options, fn, &kDoubleCodec);
      } catch (...) {
        o.error = std::current_exception();
      }
    });
  for (std::thread& t : ranks) t.join();
  return out;
}

TEST(Spread, EveryRankCountGivesEveryRankTheOneProcessResults) {
  constexpr std::size_t n = 37;
  std::vector<double> one(n);
  for (std::size_t i = 0; i < n; ++i) one[i] = Value(i);
  for (int size = 1; size <= 4; ++size)
    for (int threads = 1; threads <= 2; ++threads) {
      std::atomic<int> calls{0};
      const auto outcomes = RunOnRanks(size, threads, n, [&](std::size_t i) {
        ++calls;
        return Value(i);
      });
      for (const Outcome& o : outcomes) {
        ASSERT_FALSE(o.error) << size << " ranks";
        EXPECT_EQ(o.results, one) << size << " ranks x " << threads << " threads";
      }
      EXPECT_EQ(calls, static_cast<int>(n)) << "each index runs on one rank only";
    }
}

TEST(Spread, AnEmptyBatchGivesNothingOnEveryRank) {
  for (const Outcome& o : RunOnRanks(3, 1, 0, Value)) {
    EXPECT_FALSE(o.error);
    EXPECT_TRUE(o.results.empty());
  }
}

// Indices 5 and 7 fail (ranks 2 and 1 of 3 run them): every rank throws index
// 5's InputError, fields and all, as one process would.
TEST(Spread, EveryRankThrowsTheErrorOfTheLowestFailingIndex) {
  const auto fn = [](std::size_t i) {
    if (i == 5 || i == 7)
      throw InputError("cycle.json", "/cycles/" + std::to_string(i), std::to_string(i),
                       "fails here");
    return Value(i);
  };
  std::string one;
  try {
    RunnerOptions options;
    options.progress = false;
    RunIndexed<double>(20, options, fn, &kDoubleCodec);
  } catch (const InputError& e) {
    one = e.what();
  }
  ASSERT_EQ(one, "cycle.json: /cycles/5 = 5: fails here");
  for (int threads = 1; threads <= 2; ++threads)
    for (const Outcome& o : RunOnRanks(3, threads, 20, fn)) {
      ASSERT_TRUE(o.error);
      try {
        std::rethrow_exception(o.error);
      } catch (const InputError& e) {
        EXPECT_EQ(e.what(), one);
        EXPECT_EQ(e.where(), "/cycles/5");
      } catch (...) {
        ADD_FAILURE() << "not an InputError";
      }
    }
}

TEST(Spread, AStopRequestStopsEveryRank) {
  RequestStopForTesting();
  const auto outcomes = RunOnRanks(2, 1, 10, Value);
  ClearStopForTesting();
  for (const Outcome& o : outcomes) {
    ASSERT_TRUE(o.error);
    try {
      std::rethrow_exception(o.error);
    } catch (const Interrupted& e) {
      EXPECT_NE(std::string(e.what()).find("stopped on request after 0 of 10"),
                std::string::npos)
          << e.what();
    } catch (...) {
      ADD_FAILURE() << "not Interrupted";
    }
  }
}

// A batch that failed at index 30 on 2 ranks leaves rank 0's journal with
// every index below 30 (both ranks' results); resumed on 3 ranks, only the
// rest runs, and the results are the one-process ones.
TEST(Spread, RankZerosJournalHoldsEveryRanksResultsAndResumesOnAnotherCount) {
  const std::string dir =
      (fs::path(::testing::TempDir()) / "spread_test_journal").string();
  fs::remove_all(dir);
  const nlohmann::json identity = {{"invocation", {{"seed", 1}}}, {"build", "x"}};
  constexpr std::size_t n = 40;
  {
    Journal journal(dir, identity, false);
    const auto outcomes = RunOnRanks(
        2, 1, n,
        [](std::size_t i) {
          if (i == 30)
            throw ComputationError(ComputationError::Reason::kRefused, "index 30 fails");
          return Value(i);
        },
        &journal);
    for (const Outcome& o : outcomes) ASSERT_TRUE(o.error);
    EXPECT_GE(journal.written(), 30);
  }
  Journal journal(dir, identity, true);
  std::atomic<int> calls{0};
  const auto outcomes = RunOnRanks(
      3, 2, n,
      [&](std::size_t i) {
        ++calls;
        EXPECT_GE(i, 30u) << "index " << i << " was journaled";
        return Value(i);
      },
      &journal);
  EXPECT_EQ(journal.reused() + calls, static_cast<int>(n));
  EXPECT_GE(journal.reused(), 30);
  for (const Outcome& o : outcomes) {
    ASSERT_FALSE(o.error);
    for (std::size_t i = 0; i < n; ++i) EXPECT_EQ(o.results[i], Value(i)) << i;
  }
  fs::remove_all(dir);
}

// Rank 0's journal refuses the batch (its size is not the journaled one's):
// every rank throws that InputError, none waits for a rank that stopped.
TEST(Spread, AJournalRefusalOnRankZeroStopsEveryRank) {
  const std::string dir =
      (fs::path(::testing::TempDir()) / "spread_test_refusal").string();
  fs::remove_all(dir);
  const nlohmann::json identity = {{"invocation", {{"seed", 1}}}, {"build", "x"}};
  {
    Journal journal(dir, identity, false);
    for (const Outcome& o : RunOnRanks(2, 1, 10, Value, &journal)) ASSERT_FALSE(o.error);
  }
  Journal journal(dir, identity, true);
  for (const Outcome& o : RunOnRanks(3, 1, 11, Value, &journal)) {
    ASSERT_TRUE(o.error);
    try {
      std::rethrow_exception(o.error);
    } catch (const InputError& e) {
      EXPECT_NE(e.file().find("batch-0.log"), std::string::npos) << e.what();
    } catch (...) {
      ADD_FAILURE() << "not an InputError";
    }
  }
  fs::remove_all(dir);
}

// Each class a run throws comes back from its bytes as it went.
TEST(Spread, ErrorsTravelAsBytesAndComeBackAsTheyWent) {
  const auto round_trip = [](auto error) {
    try {
      ThrowEncodedException(EncodeException(std::make_exception_ptr(error)));
    } catch (...) {
      return std::current_exception();
    }
    return std::exception_ptr();
  };
  try {
    std::rethrow_exception(round_trip(InputError("f.json", "/a", "3", "must be 2")));
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "f.json");
    EXPECT_EQ(e.where(), "/a");
    EXPECT_EQ(e.value(), "3");
    EXPECT_EQ(e.rule(), "must be 2");
  }
  try {
    std::rethrow_exception(round_trip(
        ComputationError(ComputationError::Reason::kZeroVariance, "no spread")));
  } catch (const ComputationError& e) {
    EXPECT_EQ(e.reason(), ComputationError::Reason::kZeroVariance);
    EXPECT_STREQ(e.what(), "no spread");
  }
  try {
    std::rethrow_exception(round_trip(Interrupted("stopped")));
  } catch (const Interrupted& e) {
    EXPECT_STREQ(e.what(), "stopped");
  }
  try {
    std::rethrow_exception(round_trip(std::bad_alloc()));
  } catch (const ComputationError& e) {
    EXPECT_EQ(e.reason(), ComputationError::Reason::kRefused);
    EXPECT_STREQ(e.what(), std::bad_alloc().what());
  }
  EXPECT_THROW(ThrowEncodedException("\x01"), ComputationError);  // cut short
}

// AllAgree: a step that throws on one rank only is thrown on every rank.
TEST(Spread, AllAgreeThrowsOneRanksRefusalOnEveryRank) {
  ThreadGroup group(3);
  std::vector<std::string> seen(3);
  std::vector<std::thread> ranks;
  for (int r = 0; r < 3; ++r)
    ranks.emplace_back([&, r] {
      const ThreadRank rank(&group, r);
      try {
        AllAgree(&rank, [r] {
          if (r == 1) throw InputError("out", "", "dir", "refused on rank 1");
        });
      } catch (const InputError& e) {
        seen[static_cast<std::size_t>(r)] = e.what();
      }
    });
  for (std::thread& t : ranks) t.join();
  for (const std::string& s : seen) EXPECT_EQ(s, "out = dir: refused on rank 1");
}

// Without ranks (one process) AllAgree runs the step alone, its error as
// thrown.
TEST(Spread, AllAgreeWithoutRanksRunsTheStepAlone) {
  int runs = 0;
  AllAgree(nullptr, [&] { ++runs; });
  EXPECT_EQ(runs, 1);
  EXPECT_THROW(AllAgree(nullptr, [] { throw InputError("out", "", "dir", "refused"); }),
               InputError);
}

}  // namespace
}  // namespace vahf::experiment
