// Monte Carlo over trial indices on a pool of threads (docs/design.md, "Runner").
//
// Results are stored by trial index and returned in index order, so the output
// never depends on the thread count or on scheduling (docs/design.md, decision 9). Each
// trial must own everything it mutates: `fn` is called concurrently from several threads.
#pragma once

#include <cstddef>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "vahf/experiment/interrupt.h"

namespace vahf::experiment {

struct RunnerOptions {
  int threads = 1;              // worker threads, >= 1
  std::string label;            // names the run on the progress line
  std::string unit = "trials";  // what one index is, on the progress line
  bool progress = true;         // print the progress line (progress.h)
  std::FILE* progress_stream = stderr;
};

namespace internal {
// Calls body(i) for every i in [0, n) on the worker threads; the contract of
// RunIndexed below. body must not throw for a reason other than fn's.
void RunIndices(std::size_t n, const RunnerOptions& options,
                const std::function<void(std::size_t)>& body);
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
template <class R>
std::vector<R> RunIndexed(std::size_t n, const RunnerOptions& options,
                          const std::function<R(std::size_t)>& fn) {
  // optional<R>: R need not be default-constructible; each worker writes only
  // the slots of the indices it took.
  std::vector<std::optional<R>> slots(n);
  internal::RunIndices(n, options, [&](std::size_t i) { slots[i].emplace(fn(i)); });
  std::vector<R> results;
  results.reserve(n);
  for (std::optional<R>& slot : slots) results.push_back(std::move(*slot));
  return results;
}

}  // namespace vahf::experiment
