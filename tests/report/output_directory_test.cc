// The output directory appears whole at Commit() or not at all: nothing at
// PATH while staging or after an abandoned run; a previous output is replaced
// entirely; folders that are not vahf outputs are never replaced; errors name
// the path and the operating system's reason; a journal with finished work
// outlives a stopped run, for --resume; --resume with nothing journaled
// starts afresh, and refuses the finished output of the same run.
#include "vahf/report/output_directory.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "vahf/core/error.h"

namespace vahf::report {
namespace {
namespace fs = std::filesystem;

std::string Read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

class OutputDirectoryTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ =
        fs::path(::testing::TempDir()) /
        ("output_directory_test_" +
         std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(root_);
    fs::create_directories(root_);
  }
  void TearDown() override { fs::remove_all(root_); }

  std::string Under(const std::string& name) const { return (root_ / name).string(); }

  fs::path root_;
};

TEST_F(OutputDirectoryTest, NothingAppearsBeforeCommit) {
  const std::string path = Under("run");
  {
    OutputDirectory out(path);
    EXPECT_EQ(out.staging(), path + ".partial");
    out.Write("trials.csv", "trial\n0\n");
    out.Write("plots/time.gp", "plot x");
    EXPECT_FALSE(fs::exists(path));
    EXPECT_EQ(out.Files(), (std::vector<std::string>{"plots/time.gp", "trials.csv"}));
    out.Commit();
    EXPECT_TRUE(out.committed());
  }
  EXPECT_EQ(Read(fs::path(path) / "trials.csv"), "trial\n0\n");
  EXPECT_EQ(Read(fs::path(path) / "plots" / "time.gp"), "plot x");
  EXPECT_FALSE(fs::exists(path + ".partial"));
  EXPECT_FALSE(fs::exists(path + ".old"));
}

TEST_F(OutputDirectoryTest, AnAbandonedRunLeavesNothing) {
  const std::string path = Under("run");
  {
    OutputDirectory out(path);
    out.Write("trials.csv", "half");
  }  // an exception or Ctrl-C unwinds here without Commit
  EXPECT_FALSE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".partial"));
}

// The journal (experiment/journal.h): a run that stops with finished work
// leaves its staging directory for --resume; a fresh run refuses to drop it;
// the resumed run reads it, lists only output files, and commits without it.
TEST_F(OutputDirectoryTest, AJournalWithFinishedWorkOutlivesAStoppedRun) {
  const std::string path = Under("run");
  const nlohmann::json identity = {{"seed", 1}};
  {
    OutputDirectory out(path);
    out.OpenJournal(identity).Begin(2, "cycles")->Store(1, "cycle one");
    out.Write("trials.csv", "half");
    EXPECT_EQ(out.Journaled().written, 1);
  }  // stopped here without Commit
  EXPECT_FALSE(fs::exists(path));
  EXPECT_TRUE(fs::exists(path + ".partial/journal/identity.json"));
  try {
    OutputDirectory fresh(path);
    ADD_FAILURE() << "a fresh run dropped the journal";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path + ".partial");
    EXPECT_NE(e.rule().find("--resume continues it"), std::string::npos);
  }
  {
    OutputDirectory out(path, true);
    EXPECT_TRUE(out.Files().empty());  // the half-written table went; no journal file
    auto batch = out.OpenJournal(identity).Begin(2, "cycles");
    EXPECT_EQ(*batch->Find(1), "cycle one");
    batch->Store(0, "cycle zero");
    out.Write("trials.csv", "whole");
    EXPECT_EQ(out.Files(), std::vector<std::string>{"trials.csv"});
    out.Commit();
    EXPECT_EQ(out.Journaled().reused, 1);
    EXPECT_EQ(out.Journaled().written, 1);
  }
  EXPECT_EQ(Read(fs::path(path) / "trials.csv"), "whole");
  EXPECT_FALSE(fs::exists(fs::path(path) / "journal"));
  EXPECT_FALSE(fs::exists(path + ".partial"));
}

// --resume with nothing journaled yet (no staging directory; a run killed
// before its first result, with an empty, header-only or torn journal)
// starts afresh, saying why; the journal it opens is new.
TEST_F(OutputDirectoryTest, AResumeWithNothingJournaledStartsAfresh) {
  const std::string path = Under("run");
  const nlohmann::json identity = {{"seed", 1}};
  {
    OutputDirectory out(path);
    out.OpenJournal(identity).Begin(2, "cycles");
    EXPECT_EQ(out.afresh_reason(), "");
  }
  EXPECT_FALSE(fs::exists(path + ".partial"));  // a journal without work leaves nothing
  {
    OutputDirectory out(path, true);
    EXPECT_EQ(out.afresh_reason(), "there is no " + path + ".partial");
    auto batch = out.OpenJournal(identity).Begin(2, "cycles");
    EXPECT_FALSE(batch->Find(0));
    batch->Store(0, "cycle zero");
  }  // stopped with finished work: kept
  const fs::path log = path + ".partial/journal/batch-0.log";
  const std::string whole = Read(log);
  const std::size_t header = whole.find('\n') + 1;
  // What a kill before the first result leaves, and a torn first record.
  for (const std::size_t cut : {std::size_t{0}, header / 2, header, header + 7}) {
    SCOPED_TRACE("batch file cut to " + std::to_string(cut) + " bytes");
    fs::resize_file(log, cut);
    OutputDirectory out(path, true);
    EXPECT_EQ(out.afresh_reason(), path + ".partial holds no finished result");
    EXPECT_FALSE(fs::exists(log));  // the staging directory is new
    auto batch = out.OpenJournal(identity).Begin(2, "cycles");
    EXPECT_FALSE(batch->Find(0));
    batch->Store(0, "cycle zero");
    EXPECT_EQ(Read(log), whole);
  }
  // A staging directory without a journal, and a journal without batches.
  fs::remove_all(path + ".partial/journal/batch-0.log");
  { EXPECT_NE(OutputDirectory(path, true).afresh_reason(), ""); }
  fs::create_directories(path + ".partial");
  { EXPECT_NE(OutputDirectory(path, true).afresh_reason(), ""); }
  // With finished work, the journal is continued instead.
  {
    OutputDirectory out(path);
    out.OpenJournal(identity).Begin(2, "cycles")->Store(1, "cycle one");
  }
  OutputDirectory out(path, true);
  EXPECT_EQ(out.afresh_reason(), "");
  EXPECT_EQ(*out.OpenJournal(identity).Begin(2, "cycles")->Find(1), "cycle one");
}

// --resume onto the finished output of the same run (its manifest records
// the same invocation, build and inputs: RecordsRun) is refused, naming the
// manifest; the output stays. Another run's finished output is replaced,
// as a run without --resume would replace it.
TEST_F(OutputDirectoryTest, AResumeOfAFinishedRunIsRefused) {
  const std::string path = Under("run");
  const nlohmann::json identity = {{"invocation", {{"seed", 1}}},
                                   {"build", {{"version", "1"}}},
                                   {"inputs", {{"e.json", "aa"}}}};
  nlohmann::json manifest = identity;
  manifest.erase("inputs");
  manifest["experiment"] = {{"path", "e.json"}, {"sha256", "aa"}};
  manifest["results_digest"] = "5d60";
  {
    OutputDirectory out(path);
    out.OpenJournal(identity).Begin(1, "cycles")->Store(0, "cycle zero");
    out.Write(OutputDirectory::kMarkerFile, manifest.dump());
    out.Commit();
  }
  try {
    OutputDirectory out(path, true);
    out.OpenJournal(identity);
    ADD_FAILURE() << "a finished run was resumed";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path + "/manifest.json");
    EXPECT_EQ(e.where(), "/results_digest");
    EXPECT_EQ(e.value(), "\"5d60\"");
    EXPECT_NE(e.rule().find("there is nothing to resume"), std::string::npos);
  }
  EXPECT_EQ(Read(fs::path(path) / "manifest.json"), manifest.dump());
  EXPECT_FALSE(fs::exists(path + ".partial"));
  nlohmann::json other = identity;
  other["inputs"]["e.json"] = "bb";  // the experiment changed since
  OutputDirectory out(path, true);
  out.OpenJournal(other);
  EXPECT_NE(out.afresh_reason(), "");
  out.Write(OutputDirectory::kMarkerFile, "{}");
  out.Commit();
  EXPECT_EQ(Read(fs::path(path) / "manifest.json"), "{}");
}

TEST_F(OutputDirectoryTest, APreviousOutputIsReplacedWhole) {
  const std::string path = Under("run");
  {
    OutputDirectory first(path);
    first.Write("manifest.json", "{}");
    first.Write("only_in_first.csv", "x");
    first.Commit();
  }
  {
    OutputDirectory second(path);
    second.Write("manifest.json", "{\"run\": 2}");
    // Until the commit the first output stays complete.
    EXPECT_TRUE(fs::exists(fs::path(path) / "only_in_first.csv"));
    second.Commit();
  }
  EXPECT_EQ(Read(fs::path(path) / "manifest.json"), "{\"run\": 2}");
  EXPECT_FALSE(fs::exists(fs::path(path) / "only_in_first.csv"));
  EXPECT_FALSE(fs::exists(path + ".old"));
}

TEST_F(OutputDirectoryTest, AStaleStagingDirectoryIsRemoved) {
  const std::string path = Under("run/");  // a trailing slash names the same folder
  fs::create_directories(Under("run.partial/plots"));
  std::ofstream(Under("run.partial/stale.csv")) << "old";
  OutputDirectory out(path);
  EXPECT_EQ(out.path(), Under("run"));
  EXPECT_TRUE(out.Files().empty());
}

TEST_F(OutputDirectoryTest, PathCreatesFoldersForOtherPrograms) {
  OutputDirectory out(Under("nested/deeper/run"));
  const std::string png = out.Path("plots/time.png");
  EXPECT_EQ(png, Under("nested/deeper/run.partial/plots/time.png"));
  EXPECT_TRUE(fs::is_directory(fs::path(png).parent_path()));
}

TEST_F(OutputDirectoryTest, FoldersThatAreNotOutputsAreNeverReplaced) {
  fs::create_directories(Under("home"));
  std::ofstream(Under("home/thesis.tex")) << "precious";
  try {
    OutputDirectory out(Under("home"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), Under("home"));
    EXPECT_EQ(e.rule(),
              "exists and holds no manifest.json, so it is not a vahf output: remove it "
              "or choose another path");
  }
  EXPECT_FALSE(fs::exists(Under("home.partial")));
  std::ofstream(Under("file")) << "x";
  EXPECT_THROW(OutputDirectory(Under("file")), InputError);
  EXPECT_THROW(OutputDirectory("."), InputError);
  // An empty folder may be used.
  fs::create_directories(Under("empty"));
  OutputDirectory(Under("empty")).Commit();
}

TEST_F(OutputDirectoryTest, ACommitRechecksThePath) {
  OutputDirectory out(Under("run"));
  fs::create_directories(Under("run"));
  std::ofstream(Under("run/notes.txt")) << "appeared meanwhile";
  EXPECT_THROW(out.Commit(), InputError);
  EXPECT_EQ(Read(Under("run/notes.txt")), "appeared meanwhile");
}

TEST_F(OutputDirectoryTest, ErrorsNameThePathAndTheReason) {
  std::ofstream(Under("blocker")) << "a file where a folder should be";
  try {
    OutputDirectory out(Under("blocker/run"));
    ADD_FAILURE();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              Under("blocker") + ": cannot create the folder: Not a directory");
  }
}

using OutputDirectoryDeathTest = OutputDirectoryTest;

TEST_F(OutputDirectoryDeathTest, BadRelativeNamesAreBugs) {
  OutputDirectory out(Under("run"));
  EXPECT_DEATH(out.Write("../escape.csv", "x"), "not a plain relative path");
  EXPECT_DEATH(out.Write("/abs.csv", "x"), "not a plain relative path");
  EXPECT_DEATH(out.Write("", "x"), "not a plain relative path");
}

}  // namespace
}  // namespace vahf::report
