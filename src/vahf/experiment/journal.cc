#include "vahf/experiment/journal.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <system_error>

#include "vahf/core/atomic_file.h"
#include "vahf/core/digest.h"
#include "vahf/core/error.h"
#include "vahf/core/whole_file.h"

namespace vahf::experiment {
namespace {

namespace fs = std::filesystem;

constexpr const char* kBatchFormat = "vahf-journal-batch/1";
constexpr const char* kIdentityFile = "identity.json";

[[noreturn]] void Refused(const std::string& what, const std::string& path, int error) {
  throw ComputationError(
      ComputationError::Reason::kRefused,
      fmt::format("journal: cannot {} {}: {}", what, path, std::strerror(error)));
}

// A batch or identity file; empty when there is none yet.
std::string ReadAll(const std::string& path) { return ReadWholeFile(path).value_or(""); }

// What a record's digest covers: its index, its length and its bytes.
std::string RecordDigest(std::size_t index, const std::string& bytes) {
  Sha256 sha;
  sha.Update(fmt::format("{} {}\n", index, bytes.size()));
  sha.Update(bytes);
  return sha.HexDigest();
}

std::string Shown(const nlohmann::json& value) {
  const std::string text = value.is_null() ? "(none)" : value.dump();
  return text.size() <= 100 ? text
                            : text.substr(0, 60) + "..." + text.substr(text.size() - 37);
}

// Reads one "entry INDEX LENGTH SHA256\n" record at `pos`; false if it does
// not check (torn, zeroed, or not a record).
bool ReadRecord(const std::string& text, std::size_t* pos, std::size_t* index,
                std::string* bytes) {
  const std::size_t end = text.find('\n', *pos);
  if (end == std::string::npos) return false;
  std::istringstream line(text.substr(*pos, end - *pos));
  std::string word, sha;
  std::size_t length = 0;
  if (!(line >> word >> *index >> length >> sha) || word != "entry") return false;
  const std::size_t start = end + 1;
  if (length > text.size() || start + length >= text.size() ||
      text[start + length] != '\n')
    return false;
  *bytes = text.substr(start, length);
  if (RecordDigest(*index, *bytes) != sha) return false;
  *pos = start + length + 1;
  return true;
}

// The value at `pointer` in `json`, as a message shows it; "(none)" where
// there is none.
std::string ShownAt(const nlohmann::json& json, const std::string& pointer) {
  const nlohmann::json::json_pointer p(pointer);
  return json.contains(p) ? Shown(json.at(p)) : "(none)";
}

// Refuses a journal whose identity (journal.h) differs from this command's
// in any member this command has, naming the first place it differs: within
// a member, the first entry JSON Patch's diff gives (RFC 6902), so that of
// the inputs the one file that changed is named with its digests.
void CheckIdentity(const std::string& identity_path, const nlohmann::json& journaled,
                   const nlohmann::json& identity) {
  for (const auto& [key, value] : identity.items()) {
    const std::string member = (nlohmann::json::json_pointer() / key).to_string();
    if (journaled.is_object() && journaled.contains(key) && journaled[key] == value)
      continue;
    std::string where = member;
    if (journaled.is_object() && journaled.contains(key)) {
      const nlohmann::json patch = nlohmann::json::diff(journaled[key], value);
      if (!patch.empty()) where += patch[0]["path"].get<std::string>();
    }
    throw InputError(
        identity_path, where,
        journaled.is_object() ? ShownAt(journaled, where) : "(none)",
        fmt::format("the journaled run had this; this command gives {}: --resume "
                    "continues only the same run (without it, the run starts afresh)",
                    ShownAt(identity, where)));
  }
}

}  // namespace

Journal::Journal(std::string directory, const nlohmann::json& identity, bool resume)
    : directory_(std::move(directory)), resume_(resume) {
  const std::string identity_path = (fs::path(directory_) / kIdentityFile).string();
  std::error_code error;
  if (!resume) {
    fs::remove_all(directory_, error);
    fs::create_directories(directory_, error);
    if (error) Refused("create", directory_, error.value());
    // identity.json and the journal's folder entry are on disk before any
    // record counts as kept.
    WriteFileAtomically(identity_path, identity.dump(1) + "\n");
    const fs::path parent = fs::path(directory_).parent_path();
    error = SyncDirectory(parent.empty() ? "." : parent.string());
    if (error) Refused("sync the folder of", directory_, error.value());
    return;
  }
  if (!fs::is_regular_file(identity_path, error))
    throw InputError(identity_path, "", "",
                     "is missing: there is no journaled run here to resume");
  const nlohmann::json journaled = nlohmann::json::parse(ReadAll(identity_path), nullptr,
                                                         /*allow_exceptions=*/false);
  CheckIdentity(identity_path, journaled, identity);
}

Journal::~Journal() = default;

bool Journal::HoldsResults(const std::string& directory) {
  std::error_code error;
  for (fs::directory_iterator it(directory, error), end; !error && it != end;
       it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.rfind("batch-", 0) != 0 || it->path().extension() != ".log") continue;
    const std::string text = ReadAll(it->path().string());
    std::size_t pos = text.find('\n');
    if (pos == std::string::npos ||
        text.compare(0, std::strlen(kBatchFormat), kBatchFormat) != 0)
      continue;
    ++pos;
    std::size_t index = 0;
    std::string bytes;
    if (ReadRecord(text, &pos, &index, &bytes)) return true;
  }
  return false;
}

std::unique_ptr<Journal::Batch> Journal::Begin(std::size_t indices,
                                               const std::string& label) {
  const std::string path =
      (fs::path(directory_) / fmt::format("batch-{}.log", batches_++)).string();
  std::unique_ptr<Batch> batch(new Batch(this, path));
  const std::string header = fmt::format("{} {} {}\n", kBatchFormat, indices, label);
  std::size_t good = 0;  // bytes of the file that check
  if (resume_) {
    const std::string text = ReadAll(path);
    if (text.compare(0, header.size(), header) == 0) {
      good = header.size();
      std::size_t index = 0;
      std::string bytes;
      while (ReadRecord(text, &good, &index, &bytes))
        batch->entries_.emplace(index, bytes);
      if (good < text.size()) ++torn_;
    } else if (text.compare(0, std::strlen(kBatchFormat), kBatchFormat) == 0 &&
               text.find('\n') != std::string::npos) {
      throw InputError(
          path, "line 1", text.substr(0, text.find('\n')),
          fmt::format(
              "the journaled run's batch differs from this run's ({}): the inputs "
              "or the program changed; run without --resume to start afresh",
              header.substr(0, header.size() - 1)));
    }
  }
  batch->fd_ = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (batch->fd_ < 0) Refused("open", path, errno);
  if (::ftruncate(batch->fd_, static_cast<off_t>(good)) != 0) Refused("cut", path, errno);
  if (good == 0) {
    batch->Append(header);
    const std::error_code synced = SyncDirectory(directory_);  // the new file's name
    if (synced) Refused("sync", directory_, synced.value());
  }
  return batch;
}

Journal::Batch::Batch(Journal* journal, std::string path)
    : journal_(journal), path_(std::move(path)) {}

Journal::Batch::~Batch() {
  if (fd_ >= 0) ::close(fd_);
}

std::optional<std::string> Journal::Batch::Find(std::size_t index) {
  const auto it = entries_.find(index);
  if (it == entries_.end()) return std::nullopt;
  ++journal_->reused_;
  return it->second;
}

void Journal::Batch::Store(std::size_t index, const std::string& bytes) {
  Append(
      fmt::format("entry {} {} {}\n", index, bytes.size(), RecordDigest(index, bytes)) +
      bytes + "\n");
  ++journal_->written_;
}

void Journal::Batch::Append(const std::string& record) {
  const std::lock_guard<std::mutex> lock(write_mutex_);
  std::size_t done = 0;
  while (done < record.size()) {
    const ssize_t n = ::write(fd_, record.data() + done, record.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) Refused("write", path_, n < 0 ? errno : EIO);
    done += static_cast<std::size_t>(n);
  }
  // On disk before the record counts as kept (about 0.5 ms, against a
  // cycle's 600 ms).
  while (::fdatasync(fd_) != 0)
    if (errno != EINTR) Refused("sync", path_, errno);
}

}  // namespace vahf::experiment
