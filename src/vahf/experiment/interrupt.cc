#include "vahf/experiment/interrupt.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <system_error>

#include "vahf/core/error.h"

namespace vahf::experiment {
namespace {

// A signal handler may only touch lock-free atomics (C++17 [support.signal]).
static_assert(std::atomic<bool>::is_always_lock_free);
std::atomic<bool> stop_requested{false};

extern "C" void OnStopSignal(int /*signal*/) {
  stop_requested.store(true, std::memory_order_relaxed);
}

}  // namespace

void InstallInterruptHandler() {
  struct sigaction action;
  std::memset(&action, 0, sizeof action);
  action.sa_handler = OnStopSignal;
  sigemptyset(&action.sa_mask);
  // SA_RESTART: system calls interrupted by the signal resume, so file writes
  // in progress complete; SA_RESETHAND: the next signal takes the default action.
  action.sa_flags = SA_RESTART | SA_RESETHAND;
  for (int signal : {SIGINT, SIGTERM}) {
    if (sigaction(signal, &action, nullptr) != 0) {
      throw ComputationError(ComputationError::Reason::kRefused,
                             "sigaction: " + std::generic_category().message(errno));
    }
  }
}

bool StopRequested() { return stop_requested.load(std::memory_order_relaxed); }

void RequestStop() { stop_requested.store(true, std::memory_order_relaxed); }

void ClearStop() { stop_requested.store(false, std::memory_order_relaxed); }

void RequestStopForTesting() { stop_requested.store(true, std::memory_order_relaxed); }

void ClearStopForTesting() { stop_requested.store(false, std::memory_order_relaxed); }

}  // namespace vahf::experiment
