// A run's journal (docs/reproducibility.md, "Resume"): every finished index
// of every parallel batch of a run (a design's cycles, a calibration's
// design evaluations, a stability suite's trials), kept as it finishes, so
// that a run stopped by Ctrl-C, kill -9 or a power loss can be resumed and
// run only what is missing.
//
// A batch is one RunIndexed call (runner.h). A run makes its batches in the
// same order every time it is given the same inputs (its results, hence its
// control flow, are the same bits), so the k-th batch of a resumed run is the
// k-th batch of the run it resumes. Batch k is the file batch-K.log: a header
// line, then one record per finished index, appended under a lock:
//
//   vahf-journal-batch/1 INDICES LABEL\n
//   entry INDEX LENGTH SHA256\n  LENGTH bytes (result_codec.h)  \n
//
// A record is one write(), synced to disk (fdatasync) before it counts as
// kept; identity.json and each batch file's name are synced in their folder
// when created. After kill -9 every record written is complete; a record
// being written when the disk filled or the power failed may be torn.
// Reading stops at the first record that does not check (its digest is over
// the index, the length and the bytes) and cuts the file there: what is lost
// is run again, never read wrong.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace vahf::experiment {

class Journal {
 public:
  class Batch;

  // Opens the journal in `directory` for a run described by `identity` (the
  // command that started it, the digests of its files, the build: what
  // must be equal for its results to be reused). Fresh (resume false):
  // removes whatever is in `directory` and writes identity.json. Resume:
  // `directory` must hold identity.json equal to `identity`; else an
  // InputError names identity.json, the first differing field, both values
  // and the rule.
  Journal(std::string directory, const nlohmann::json& identity, bool resume);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  // Whether `directory` holds a journal with finished work: a batch file
  // with at least one whole record that checks. A journal killed before its
  // first result (no batch file, a header alone, a torn first record) holds
  // none: nothing is lost by starting afresh.
  static bool HoldsResults(const std::string& directory);

  // The run's next batch of `indices` indices, its label for the header. On
  // resume, its entries are read back (a header for another number of
  // indices is an InputError: the run is not the one journaled).
  std::unique_ptr<Batch> Begin(std::size_t indices, const std::string& label);

  const std::string& directory() const { return directory_; }
  // Entries read back and used, written, and cut off as torn, so far.
  std::int64_t reused() const { return reused_; }
  std::int64_t written() const { return written_; }
  std::int64_t torn() const { return torn_; }

 private:
  friend class Batch;
  std::string directory_;
  bool resume_;
  int batches_ = 0;
  std::atomic<std::int64_t> reused_{0}, written_{0}, torn_{0};
};

class Journal::Batch {
 public:
  ~Batch();
  Batch(const Batch&) = delete;
  Batch& operator=(const Batch&) = delete;

  // The bytes journaled for `index`, if any (counted as reused).
  std::optional<std::string> Find(std::size_t index);
  // Appends `index`'s bytes and syncs them to disk; safe from several
  // threads. A write or sync the system refuses (a full disk) is a
  // ComputationError (kRefused) naming the file.
  void Store(std::size_t index, const std::string& bytes);

 private:
  friend class Journal;
  Batch(Journal* journal, std::string path);
  void Append(const std::string& record);  // one write() and a sync, under the lock

  Journal* journal_;
  std::string path_;
  int fd_ = -1;
  std::mutex write_mutex_;
  std::map<std::size_t, std::string> entries_;
};

}  // namespace vahf::experiment
