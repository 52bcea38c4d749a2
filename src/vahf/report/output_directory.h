// A run's output directory, written whole or not at all (docs/design.md, "Outputs";
// docs/outputs.md). Every file is staged in a sibling directory PATH.partial;
// Commit() swaps it in for PATH with renames, so PATH holds either the previous
// complete output or the new complete output, never a mixture or a part.
// The staging directory also holds the run's journal (experiment/journal.h,
// docs/reproducibility.md "Resume"), which outlives a run that stops with
// finished cycles, so that the same command with --resume continues it.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "vahf/experiment/journal.h"

namespace vahf::report {

class OutputDirectory {
 public:
  // An existing PATH is replaced only if it is a directory that is empty or
  // holds this file (a previous run's output): a mistyped path never deletes
  // someone's files.
  static constexpr const char* kMarkerFile = "manifest.json";

  // Checks that PATH may be replaced, creates its parent folders, and creates
  // PATH.partial fresh (removing one a failed run left, unless it holds a
  // stopped run's journal: that is an InputError saying --resume continues
  // it). With `resume`, a journal with finished work in PATH.partial is kept
  // (the files staged beside it are removed); where there is none (no
  // PATH.partial, or a run stopped before its first result) the run starts
  // afresh, as afresh_reason() says. Failures are InputErrors naming the
  // path and the operating system's reason.
  explicit OutputDirectory(const std::string& path, bool resume = false);
  // Without Commit(), removes the staging directory, unless its journal
  // holds finished work: PATH is untouched.
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  const std::string& path() const { return path_; }        // where Commit() puts it
  const std::string& staging() const { return staging_; }  // PATH.partial

  // Writes `bytes` to `relative` ("table.csv", "plots/time.png") in staging,
  // creating folders on the way. `relative` must be a plain relative path
  // without "." or ".." parts (else a bug).
  void Write(const std::string& relative, std::string_view bytes);

  // The staging path of `relative`, its folders created, for a file another
  // program writes (a gnuplot plot).
  std::string Path(const std::string& relative);

  // The regular files staged so far, relative, '/'-separated, sorted by name.
  std::vector<std::string> Files() const;

  // Why a `resume` found nothing to continue and the run starts afresh
  // ("there is no PATH.partial", "PATH.partial holds no finished result");
  // empty when it continues a journal or was not asked to resume.
  const std::string& afresh_reason() const { return afresh_reason_; }

  // Opens the run's journal in PATH.partial/journal (Journal's constructor:
  // fresh, or the one to resume, which must have the same `identity`). A
  // `resume` that starts afresh refuses, with an InputError naming
  // PATH/manifest.json, when PATH holds the finished output of this same
  // run (report::RecordsRun): there is nothing to resume.
  experiment::Journal& OpenJournal(const nlohmann::json& identity);
  // The journal's entries reused from a stopped run and written by this one,
  // so far (kept after Commit()); zeros without a journal.
  struct JournalCounts {
    std::int64_t reused = 0, written = 0;
    std::int64_t total() const { return reused + written; }
  };
  JournalCounts Journaled() const;

  // Removes the journal, then replaces PATH by the staged directory: renames
  // PATH to PATH.old (removing a stale one), renames PATH.partial to PATH,
  // then removes PATH.old and syncs PATH's folder to disk. If the second
  // rename fails, PATH.old is renamed back. Once only.
  void Commit();
  bool committed() const { return committed_; }

 private:
  std::string StagedPath(const std::string& relative) const;

  std::string path_;
  std::string staging_;
  bool resume_ = false;  // a journal with finished work is continued
  std::string afresh_reason_;
  std::unique_ptr<experiment::Journal> journal_;
  JournalCounts closed_;  // the counts of the journal, once closed
  bool committed_ = false;
};

}  // namespace vahf::report
