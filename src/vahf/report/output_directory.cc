#include "vahf/report/output_directory.h"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <system_error>

#include "vahf/core/atomic_file.h"
#include "vahf/core/error.h"
#include "vahf/core/whole_file.h"
#include "vahf/report/manifest.h"

namespace vahf::report {
namespace fs = std::filesystem;
namespace {

[[noreturn]] void Fail(const std::string& path, const std::string& what,
                       const std::error_code& ec) {
  throw InputError(path, "", "", what + ": " + ec.message());
}

// PATH without trailing separators, so that PATH.partial is a sibling.
std::string Normalize(const std::string& path) {
  if (path.empty()) throw InputError("", "", "", "the output directory path is empty");
  std::string p = fs::path(path).lexically_normal().string();
  while (p.size() > 1 && p.back() == '/') p.pop_back();
  if (p == "." || p == ".." || p == "/") {
    throw InputError(path, "", "", "cannot be an output directory: name a new folder");
  }
  return p;
}

// May `path` be replaced? Missing, an empty folder, or a previous output.
void CheckReplaceable(const std::string& path) {
  std::error_code ec;
  const fs::file_status status = fs::symlink_status(path, ec);
  if (status.type() == fs::file_type::not_found) return;
  if (ec) Fail(path, "cannot inspect the output directory", ec);
  if (status.type() != fs::file_type::directory) {
    throw InputError(path, "", "",
                     "exists and is not a directory: choose another output path");
  }
  const bool empty = fs::is_empty(path, ec);
  if (ec) Fail(path, "cannot read the output directory", ec);
  if (!empty && !fs::exists(fs::path(path) / OutputDirectory::kMarkerFile, ec)) {
    throw InputError(
        path, "", "",
        std::string("exists and holds no ") + OutputDirectory::kMarkerFile +
            ", so it is not a vahf output: remove it or choose another path");
  }
}

constexpr const char* kJournal = "journal";

// Whether the staging directory holds a journal with finished work.
bool HoldsJournal(const std::string& staging) {
  return experiment::Journal::HoldsResults((fs::path(staging) / kJournal).string());
}

// A --resume onto the finished output of the same run: nothing to resume.
void RefuseFinishedRun(const std::string& path, const nlohmann::json& identity) {
  const std::string manifest_path =
      (fs::path(path) / OutputDirectory::kMarkerFile).string();
  const std::optional<std::string> text = ReadWholeFile(manifest_path);
  if (!text) return;
  const nlohmann::json manifest =
      nlohmann::json::parse(*text, nullptr, /*allow_exceptions=*/false);
  if (!RecordsRun(manifest, identity)) return;
  const nlohmann::json digest = manifest.value("results_digest", nlohmann::json());
  throw InputError(manifest_path, "/results_digest", digest.dump(),
                   "this same run has finished (the same invocation, inputs and "
                   "build): there is nothing to resume; without --resume it runs "
                   "again and replaces this output");
}

}  // namespace

OutputDirectory::OutputDirectory(const std::string& path, bool resume)
    : path_(Normalize(path)), staging_(path_ + ".partial") {
  CheckReplaceable(path_);
  std::error_code ec;
  const fs::path parent = fs::path(path_).parent_path();
  if (!parent.empty()) {
    fs::create_directories(parent, ec);
    if (ec) Fail(parent.string(), "cannot create the folder", ec);
  }
  const bool journal = HoldsJournal(staging_);
  if (resume && journal) {
    resume_ = true;
    // The journal stays; files a stopped output write left go.
    for (fs::directory_iterator it(staging_, ec), end; !ec && it != end; it.increment(ec))
      if (it->path().filename() != kJournal) fs::remove_all(it->path(), ec);
    if (ec) Fail(staging_, "cannot clear the staging directory", ec);
    return;
  }
  if (journal)
    throw InputError(staging_, "", "",
                     "holds the journal of a stopped run: the same command with --resume "
                     "continues it; remove the folder to start afresh");
  // A --resume with nothing journaled (no staging directory, or a run stopped
  // before its first result) starts afresh: no work is lost.
  if (resume)
    afresh_reason_ = fs::exists(staging_, ec) ? staging_ + " holds no finished result"
                                              : "there is no " + staging_;
  fs::remove_all(staging_, ec);
  if (ec) Fail(staging_, "cannot remove the staging directory of an earlier run", ec);
  fs::create_directory(staging_, ec);
  if (ec) Fail(staging_, "cannot create the staging directory", ec);
  // Its name is on disk before the journal inside it keeps anything.
  if (const std::error_code synced =
          SyncDirectory(parent.empty() ? "." : parent.string()))
    Fail(parent.string(), "cannot sync the folder to disk", synced);
}

OutputDirectory::~OutputDirectory() {
  if (committed_) return;
  journal_.reset();
  // A journal with finished work stays, also one a refused --resume found.
  const bool keep = HoldsJournal(staging_);
  std::error_code ec;
  if (!keep) fs::remove_all(staging_, ec);  // best effort: a destructor must not throw
}

experiment::Journal& OutputDirectory::OpenJournal(const nlohmann::json& identity) {
  VAHF_CHECK(!journal_ && !committed_, "one journal per output, before Commit()");
  if (!afresh_reason_.empty()) RefuseFinishedRun(path_, identity);
  journal_ = std::make_unique<experiment::Journal>(
      (fs::path(staging_) / kJournal).string(), identity, resume_);
  return *journal_;
}

OutputDirectory::JournalCounts OutputDirectory::Journaled() const {
  if (!journal_) return closed_;
  return {journal_->reused(), journal_->written()};
}

std::string OutputDirectory::StagedPath(const std::string& relative) const {
  const fs::path r(relative);
  const bool plain = !relative.empty() && r.is_relative() &&
                     std::none_of(r.begin(), r.end(), [](const fs::path& part) {
                       return part == "." || part == ".." || part.empty();
                     });
  VAHF_CHECK(plain, "output file name '" + relative + "' is not a plain relative path");
  VAHF_CHECK(!committed_, "writing '" + relative + "' after Commit()");
  return (fs::path(staging_) / r).string();
}

void OutputDirectory::Write(const std::string& relative, std::string_view bytes) {
  WriteFileAtomically(Path(relative), std::string(bytes));
}

std::string OutputDirectory::Path(const std::string& relative) {
  const std::string staged = StagedPath(relative);
  const fs::path parent = fs::path(staged).parent_path();
  std::error_code ec;
  fs::create_directories(parent, ec);
  if (ec) Fail(parent.string(), "cannot create the folder", ec);
  return staged;
}

std::vector<std::string> OutputDirectory::Files() const {
  std::vector<std::string> names;
  const fs::path root = committed_ ? path_ : staging_;
  std::error_code ec;
  for (fs::recursive_directory_iterator it(root, ec), end; !ec && it != end;
       it.increment(ec)) {
    const std::string name = it->path().lexically_relative(root).generic_string();
    if (name == kJournal) it.disable_recursion_pending();  // not an output file
    if (name != kJournal && it->is_regular_file(ec)) names.push_back(name);
  }
  if (ec) Fail(root.string(), "cannot list the output files", ec);
  std::sort(names.begin(), names.end());
  return names;
}

void OutputDirectory::Commit() {
  VAHF_CHECK(!committed_, "OutputDirectory::Commit called twice");
  CheckReplaceable(path_);  // it may have appeared since the constructor
  closed_ = Journaled();
  journal_.reset();
  std::error_code ec;
  fs::remove_all(fs::path(staging_) / kJournal, ec);
  if (ec) Fail(staging_, "cannot remove the run's journal", ec);
  const std::string old = path_ + ".old";
  fs::remove_all(old, ec);
  if (ec) Fail(old, "cannot remove a stale previous output", ec);
  const bool had_old = fs::exists(path_, ec);
  if (had_old) {
    fs::rename(path_, old, ec);
    if (ec) Fail(path_, "cannot move the previous output aside", ec);
  }
  fs::rename(staging_, path_, ec);
  if (ec) {
    std::error_code ignored;
    if (had_old) fs::rename(old, path_, ignored);
    Fail(path_, "cannot move the finished output into place", ec);
  }
  committed_ = true;
  if (had_old) fs::remove_all(old, ec);  // leftovers are harmless: removed next time
  // The rename is on disk before the run counts as finished.
  const fs::path parent = fs::path(path_).parent_path();
  if (const std::error_code synced =
          SyncDirectory(parent.empty() ? "." : parent.string()))
    Fail(parent.string(), "cannot sync the folder to disk", synced);
}

}  // namespace vahf::report
