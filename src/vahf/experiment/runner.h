// Monte Carlo over trial indices on a pool of threads (docs/design.md, "Runner").
//
// Results are stored by trial index and returned in index order, so the output
// never depends on the thread count or on scheduling (docs/design.md, decision 9). Each
// trial must own everything it mutates: `fn` is called concurrently from several threads.
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vahf/experiment/interrupt.h"
#include "vahf/experiment/journal.h"
#include "vahf/experiment/ranks.h"

namespace vahf::experiment {

class ProgressSink;  // progress.h

struct RunnerOptions {
  int threads = 1;              // worker threads, >= 1
  std::string label;            // names the run on the progress line
  std::string unit = "trials";  // what one index is, on the progress line
  bool progress = true;         // print the progress line (progress.h)
  std::FILE* progress_stream = stderr;
  // Also stores the progress here (progress.h), for a host to read; null: not.
  ProgressSink* progress_sink = nullptr;
  // Keeps each finished index and resumes those it holds (journal.h), for a
  // RunIndexed given a codec; null: nothing is kept.
  Journal* journal = nullptr;
  // The processes the run is spread over (ranks.h); null or one rank: this
  // process runs every index. With several, a RunIndexed given a codec
  // runs this rank's share and gathers the rest; only rank 0 journals.
  const Ranks* ranks = nullptr;
};

// How a journal keeps a result of type R: as bytes and back, exactly
// (result_codec.h).
template <class R>
struct ResultCodec {
  std::string (*encode)(const R&);
  R (*decode)(const std::string&);
};

namespace internal {
// Calls body(i) for every i in [0, n) on the worker threads; the contract of
// RunIndexed below. body must not throw for a reason other than fn's.
void RunIndices(std::size_t n, const RunnerOptions& options,
                const std::function<void(std::size_t)>& body);
// The text of the Interrupted a stopped batch throws.
std::string StoppedMessage(const RunnerOptions& options, std::size_t done, std::size_t n);
// RunIndexed over options.ranks (several ranks): the indices the journal
// holds (rank 0's) are read, the others dealt round-robin (the k-th one
// missing goes to rank k mod size), each rank runs its share on its threads
// with `run` (fn's result encoded), and every rank gets every index's bytes,
// in index order. Rank 0 journals every result, its own as they finish, the
// others' when they arrive. Errors as RunIndices: every rank throws the
// exception of the lowest failing index, or Interrupted if a rank stopped.
std::vector<std::string> RunIndicesOnRanks(
    std::size_t n, const RunnerOptions& options,
    const std::function<std::string(std::size_t)>& run);
}  // namespace internal

// Calls fn(i) for every i in [0, n) on `options.threads` worker threads, which
// take the next index from a shared atomic counter, and returns the results
// indexed by i.
//
// Errors: once fn(k) threw, no index above k is started; every index below k
// runs to the end, and the exception of the lowest failing index is rethrown
// once all workers stopped: the same one whatever the thread count. Otherwise,
// if StopRequested() became true, indices not yet started are skipped, running
// ones finish, and Interrupted is thrown. threads < 1 is a ComputationError
// (kOutOfDomain).
// With options.journal and a codec, it is one batch of the journal: an
// index the journal holds is decoded instead of run (fn is not called for
// it), and every index run is journaled as it finishes. The results are the
// same bits either way. With options.ranks of several ranks and a codec, the
// batch is spread over them (internal::RunIndicesOnRanks): every result is
// then decoded from its bytes, on every rank, so each rank holds the same
// bits whichever rank ran an index.
template <class R>
std::vector<R> RunIndexed(std::size_t n, const RunnerOptions& options,
                          const std::function<R(std::size_t)>& fn,
                          const ResultCodec<R>* codec = nullptr) {
  if (codec && options.ranks && options.ranks->size() > 1) {
    const std::vector<std::string> bytes = internal::RunIndicesOnRanks(
        n, options, [&](std::size_t i) { return codec->encode(fn(i)); });
    std::vector<R> results;
    results.reserve(n);
    for (const std::string& b : bytes) results.push_back(codec->decode(b));
    return results;
  }
  // optional<R>: R need not be default-constructible; each worker writes only
  // the slots of the indices it took.
  std::vector<std::optional<R>> slots(n);
  if (options.journal && codec) {
    const std::unique_ptr<Journal::Batch> batch =
        options.journal->Begin(n, options.label);
    internal::RunIndices(n, options, [&](std::size_t i) {
      if (const std::optional<std::string> bytes = batch->Find(i)) {
        slots[i].emplace(codec->decode(*bytes));
      } else {
        slots[i].emplace(fn(i));
        batch->Store(i, codec->encode(*slots[i]));
      }
    });
  } else {
    internal::RunIndices(n, options, [&](std::size_t i) { slots[i].emplace(fn(i)); });
  }
  std::vector<R> results;
  results.reserve(n);
  for (std::optional<R>& slot : slots) results.push_back(std::move(*slot));
  return results;
}

}  // namespace vahf::experiment
