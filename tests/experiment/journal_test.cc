// The run journal: records stored from several threads read back exactly on
// resume, batch by batch; a torn or zeroed tail is cut and counted, and what
// is stored after it reads back; a resume of another run (identity) or of a
// batch of another size is an InputError naming the file; a file cut at
// any byte reads back its whole records; a fresh journal
// forgets the old one. RunIndexed with a journal runs only the indices it
// lacks, with the same results.
#include "vahf/experiment/journal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include <vector>

#include "vahf/core/error.h"
#include "vahf/experiment/runner.h"

namespace vahf::experiment {
namespace {
namespace fs = std::filesystem;

class JournalTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        (fs::path(::testing::TempDir()) /
         ("journal_test_" +
          std::string(::testing::UnitTest::GetInstance()->current_test_info()->name())))
            .string();
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Log(int batch) const {
    return (fs::path(dir_) / ("batch-" + std::to_string(batch) + ".log")).string();
  }

  const nlohmann::json identity_ = {{"invocation", {{"seed", 1}}}, {"build", "x"}};
  std::string dir_;
};

// Bytes of index i: of varied length, with NUL and line breaks inside.
std::string Bytes(std::size_t i) {
  return std::string(i % 7, '\n') + std::string(1, '\0') + std::to_string(i * i) +
         std::string(i % 3, 'x');
}

TEST_F(JournalTest, WhatTwoThreadsStoreReadsBackOnResume) {
  {
    Journal j(dir_, identity_, false);
    auto a = j.Begin(100, "first (table1)");
    auto b = j.Begin(3, "second");
    std::thread t1([&] {
      for (std::size_t i = 0; i < 100; i += 2) a->Store(i, Bytes(i));
    });
    std::thread t2([&] {
      for (std::size_t i = 1; i < 100; i += 2) a->Store(i, Bytes(i));
    });
    t1.join();
    t2.join();
    b->Store(2, "only");
    EXPECT_EQ(j.written(), 101);
    EXPECT_FALSE(a->Find(0));  // a fresh journal reuses nothing
  }
  Journal j(dir_, identity_, true);
  auto a = j.Begin(100, "first (table1)");
  auto b = j.Begin(3, "second");
  for (std::size_t i = 0; i < 100; ++i) {
    const auto bytes = a->Find(i);
    ASSERT_TRUE(bytes) << i;
    EXPECT_EQ(*bytes, Bytes(i)) << i;
  }
  EXPECT_FALSE(b->Find(0));
  EXPECT_EQ(*b->Find(2), "only");
  EXPECT_EQ(j.reused(), 101);
  EXPECT_EQ(j.torn(), 0);
}

TEST_F(JournalTest, ATornOrZeroedTailIsCutAndWhatFollowsReadsBack) {
  {
    Journal j(dir_, identity_, false);
    auto a = j.Begin(3, "a");
    a->Store(0, Bytes(10));
    a->Store(1, Bytes(11));
  }
  fs::resize_file(Log(0), fs::file_size(Log(0)) - 3);  // the last record torn
  {
    Journal j(dir_, identity_, true);
    auto a = j.Begin(3, "a");
    EXPECT_EQ(*a->Find(0), Bytes(10));
    EXPECT_FALSE(a->Find(1));
    EXPECT_EQ(j.torn(), 1);
    a->Store(1, Bytes(21));
    a->Store(2, Bytes(22));
  }
  std::ofstream(Log(0), std::ios::app) << std::string(4096, '\0');  // a zeroed block
  Journal j(dir_, identity_, true);
  auto a = j.Begin(3, "a");
  EXPECT_EQ(*a->Find(0), Bytes(10));
  EXPECT_EQ(*a->Find(1), Bytes(21));
  EXPECT_EQ(*a->Find(2), Bytes(22));
  EXPECT_EQ(j.torn(), 1);
}

TEST_F(JournalTest, ARecordWhoseBytesChangedIsNotRead) {
  {
    Journal j(dir_, identity_, false);
    j.Begin(1, "a")->Store(0, "abcdef");
  }
  std::string text;
  {
    std::ifstream in(Log(0), std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  text[text.find("abcdef")] = 'X';
  std::ofstream(Log(0), std::ios::binary | std::ios::trunc) << text;
  Journal j(dir_, identity_, true);
  EXPECT_FALSE(j.Begin(1, "a")->Find(0));
  EXPECT_EQ(j.torn(), 1);
}

// A process killed at any instant leaves a batch file cut at a record's end
// (each record is one write()); a full disk or a power loss may cut it
// anywhere. Cut at every byte, the file reads back exactly its whole
// records (HoldsResults from the first), and once the rest are stored it
// reads back whole.
TEST_F(JournalTest, ACutAtEveryByteReadsBackItsWholeRecords) {
  constexpr std::size_t kIndices = 4;
  {
    Journal j(dir_, identity_, false);
    auto a = j.Begin(kIndices, "a");
    for (std::size_t i = 0; i < kIndices; ++i) a->Store(i, Bytes(i + 5));
  }
  std::string text;
  {
    std::ifstream in(Log(0), std::ios::binary);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  // Where each record ends: the header line, then "entry I N SHA\n" N bytes "\n".
  std::vector<std::size_t> ends;
  for (std::size_t pos = text.find('\n') + 1; pos < text.size();) {
    const std::size_t line_end = text.find('\n', pos);
    const std::size_t length = Bytes(ends.size() + 5).size();
    pos = line_end + 1 + length + 1;
    ends.push_back(pos);
  }
  ASSERT_EQ(ends.size(), kIndices);
  ASSERT_EQ(ends.back(), text.size());
  for (std::size_t cut = 0; cut <= text.size(); ++cut) {
    SCOPED_TRACE("cut at byte " + std::to_string(cut) + " of " +
                 std::to_string(text.size()));
    std::ofstream(Log(0), std::ios::binary | std::ios::trunc) << text.substr(0, cut);
    const std::size_t whole = static_cast<std::size_t>(
        std::count_if(ends.begin(), ends.end(), [&](std::size_t e) { return e <= cut; }));
    EXPECT_EQ(Journal::HoldsResults(dir_), whole > 0);  // else --resume starts afresh
    {
      Journal j(dir_, identity_, true);
      auto a = j.Begin(kIndices, "a");
      for (std::size_t i = 0; i < kIndices; ++i) {
        const auto bytes = a->Find(i);
        ASSERT_EQ(bytes.has_value(), i < whole) << i;
        if (bytes) {
          EXPECT_EQ(*bytes, Bytes(i + 5)) << i;
        } else {
          a->Store(i, Bytes(i + 5));
        }
      }
    }
    Journal j(dir_, identity_, true);
    auto a = j.Begin(kIndices, "a");
    for (std::size_t i = 0; i < kIndices; ++i) ASSERT_EQ(a->Find(i), Bytes(i + 5)) << i;
    EXPECT_EQ(j.torn(), 0);
  }
}

// Of the inputs, the one file whose digest changed is named, as a JSON
// pointer (its '/' written ~1), with both digests.
TEST_F(JournalTest, AChangedInputIsNamedWithBothDigests) {
  nlohmann::json mine = identity_;
  mine["inputs"] = {{"lab/dataset.json", "aa"}, {"lab/trials.csv", "bb"}};
  { Journal j(dir_, mine, false); }
  nlohmann::json changed = mine;
  changed["inputs"]["lab/trials.csv"] = "cc";
  try {
    Journal j(dir_, changed, true);
    ADD_FAILURE() << "a changed lab table resumed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "/inputs/lab~1trials.csv");
    EXPECT_EQ(e.value(), "\"bb\"");
    EXPECT_NE(e.rule().find("this command gives \"cc\":"), std::string::npos);
  }
}

TEST_F(JournalTest, ResumingAnotherRunIsRefused) {
  {
    Journal j(dir_, identity_, false);
    j.Begin(4, "a")->Store(0, "x");
  }
  nlohmann::json other = identity_;
  other["invocation"]["seed"] = 2;
  try {
    Journal j(dir_, other, true);
    ADD_FAILURE() << "another seed resumed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), (fs::path(dir_) / "identity.json").string());
    // The first place the two differ, within the member.
    EXPECT_EQ(e.where(), "/invocation/seed");
    EXPECT_EQ(e.value(), "1");
    EXPECT_NE(e.rule().find("this command gives 2:"), std::string::npos);
  }
  Journal j(dir_, identity_, true);
  try {
    j.Begin(5, "a");
    ADD_FAILURE() << "a batch of another size resumed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), Log(0));
    EXPECT_EQ(e.where(), "line 1");
    EXPECT_EQ(e.value(), "vahf-journal-batch/1 4 a");
  }
  EXPECT_THROW(Journal((fs::path(dir_) / "none").string(), identity_, true), InputError);
}

TEST_F(JournalTest, AFreshJournalForgetsTheOldOne) {
  {
    Journal j(dir_, identity_, false);
    j.Begin(1, "a")->Store(0, "x");
  }
  {
    Journal j(dir_, identity_, false);
    EXPECT_FALSE(j.Begin(1, "a")->Find(0));
  }
  Journal j(dir_, identity_, true);
  EXPECT_FALSE(j.Begin(1, "a")->Find(0));
}

const ResultCodec<double> kDoubleCodec{
    [](const double& x) { return std::string(reinterpret_cast<const char*>(&x), 8); },
    [](const std::string& b) {
      double x;
      std::memcpy(&x, b.data(), 8);
      return x;
    }};

TEST_F(JournalTest, RunIndexedRunsOnlyWhatTheJournalLacks) {
  RunnerOptions options;
  options.threads = 2;
  options.progress = false;
  std::atomic<int> calls{0};
  const std::function<double(std::size_t)> fn = [&](std::size_t i) {
    ++calls;
    return 1.0 / (static_cast<double>(i) + 3.0);
  };
  std::vector<double> first;
  {
    Journal j(dir_, identity_, false);
    options.journal = &j;
    first = RunIndexed<double>(50, options, fn, &kDoubleCodec);
    EXPECT_EQ(calls, 50);
  }
  // Cut the journal to its first 20 records: those are reused, 30 run again.
  {
    std::ifstream in(Log(0), std::ios::binary);
    std::string text(std::istreambuf_iterator<char>(in), {});
    std::size_t pos = text.find('\n') + 1;
    for (int k = 0; k < 20; ++k) pos = text.find("\nentry ", pos + 8 + 1) + 1;
    in.close();
    fs::resize_file(Log(0), pos);
  }
  calls = 0;
  Journal j(dir_, identity_, true);
  options.journal = &j;
  EXPECT_EQ(RunIndexed<double>(50, options, fn, &kDoubleCodec), first);
  EXPECT_EQ(calls, 30);
  EXPECT_EQ(j.reused(), 20);
  // Without a codec nothing is journaled.
  EXPECT_EQ(RunIndexed<double>(50, options, fn), first);
  EXPECT_EQ(calls, 80);
}

}  // namespace
}  // namespace vahf::experiment
