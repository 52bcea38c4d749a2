#include "vahf/experiment/runner.h"

#include <fmt/format.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <exception>
#include <limits>
#include <mutex>
#include <thread>

#include "vahf/core/error.h"
#include "vahf/experiment/progress.h"

namespace vahf::experiment::internal {
namespace {

constexpr std::size_t kNoFailure = std::numeric_limits<std::size_t>::max();

// What the workers share. Indices are handed out in increasing order, so when
// index k is taken every index below it has been taken, and runs to the end.
struct Shared {
  std::atomic<std::size_t> next{0};
  std::atomic<std::size_t> lowest_failure{kNoFailure};
  std::atomic<bool> stopped{false};    // a stop request made a worker quit early
  std::atomic<bool> abandoned{false};  // starting the pool failed

  std::mutex mutex;  // guards everything below
  std::condition_variable changed;
  std::size_t done = 0;
  int running_workers = 0;
  std::exception_ptr failure;  // the exception of lowest_failure
};

void Work(std::size_t n, const std::function<void(std::size_t)>& body, Shared* s) {
  for (;;) {
    if (s->abandoned.load()) break;
    if (StopRequested()) {
      s->stopped.store(true);
      break;
    }
    const std::size_t i = s->next.fetch_add(1);
    // Past the end, or past a failure: the failing index decides the outcome.
    if (i >= n || i > s->lowest_failure.load()) break;
    std::exception_ptr error;
    try {
      body(i);
    } catch (...) {
      error = std::current_exception();
    }
    std::lock_guard<std::mutex> lock(s->mutex);
    if (error && i < s->lowest_failure.load()) {
      s->lowest_failure.store(i);
      s->failure = error;
    }
    ++s->done;
  }
  std::lock_guard<std::mutex> lock(s->mutex);
  --s->running_workers;
  s->changed.notify_all();
}

}  // namespace

void RunIndices(std::size_t n, const RunnerOptions& options,
                const std::function<void(std::size_t)>& body) {
  if (options.threads < 1) {
    throw ComputationError(
        ComputationError::Reason::kOutOfDomain,
        fmt::format("runner: threads = {}: must be at least 1", options.threads));
  }
  if (n == 0) return;
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  const auto elapsed_s = [&] {
    return std::chrono::duration<double>(Clock::now() - start).count();
  };

  Shared shared;
  const int workers = static_cast<int>(
      std::min<std::size_t>(static_cast<std::size_t>(options.threads), n));
  shared.running_workers = workers;
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(workers));
  try {
    for (int w = 0; w < workers; ++w)
      pool.emplace_back(Work, n, std::cref(body), &shared);
  } catch (...) {  // no thread could be started: stop those that were
    shared.abandoned.store(true);
    for (std::thread& t : pool) t.join();
    throw;
  }

  // The calling thread only watches: it wakes when a worker ends and four
  // times a second to update the progress line.
  ProgressMeter meter(options.label, n, options.progress, options.progress_stream,
                      options.unit,
                      IsTerminal(options.progress_stream) ? ProgressMeter::Style::kInPlace
                                                          : ProgressMeter::Style::kLog);
  std::size_t done = 0;
  if (options.progress_sink) options.progress_sink->Begin(options.label, options.unit, n);
  {
    std::unique_lock<std::mutex> lock(shared.mutex);
    while (shared.running_workers > 0) {
      shared.changed.wait_for(lock, std::chrono::milliseconds(250));
      done = shared.done;
      lock.unlock();
      meter.Update(done, elapsed_s());
      if (options.progress_sink) options.progress_sink->Update(done);
      lock.lock();
    }
    done = shared.done;
  }
  if (options.progress_sink) options.progress_sink->Update(done);
  for (std::thread& t : pool) t.join();
  meter.Finish(done, elapsed_s());

  if (shared.failure) std::rethrow_exception(shared.failure);
  if (shared.stopped.load() && done < n) {
    throw Interrupted(StoppedMessage(options, done, n));
  }
}

std::string StoppedMessage(const RunnerOptions& options, std::size_t done,
                           std::size_t n) {
  return fmt::format("{}{}stopped on request after {} of {} {}", options.label,
                     options.label.empty() ? "" : ": ", done, n, options.unit);
}

}  // namespace vahf::experiment::internal
