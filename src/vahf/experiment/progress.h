// The progress line of a long Monte Carlo run:
//   "label: 120/500 trials, 35.2 trials/s, about 11 s left"
// (or "cycles", whatever unit of work the run counts). On a terminal it is
// rewritten in place with a carriage return, at most twice a second; into a
// file or pipe (a CI log) it is a new line at most every 10 s, so logs stay
// readable. Nothing is printed before the run has lasted 2 s, so short runs
// print nothing. Time is passed in, not read, so the rules are testable
// without waiting.
#pragma once

#include <cstddef>
#include <cstdio>
#include <mutex>
#include <string>

namespace vahf::experiment {

// The line for `done` of `total` units (plural noun `unit`) after `elapsed_s`
// seconds; without the "label: " prefix when the label is empty.
std::string FormatProgress(const std::string& label, std::size_t done, std::size_t total,
                           double elapsed_s, const std::string& unit = "trials");

// Whether `stream` is a terminal (where a line can be rewritten in place).
bool IsTerminal(std::FILE* stream);

// Where a run's progress can be read from another thread, for a host that
// shows it itself (the Python module's callback): the runner's watching
// thread stores each batch's label, unit, done and total as it updates its
// line. The numbers only; nothing is printed.
class ProgressSink {
 public:
  struct State {
    std::string label, unit;
    std::size_t done = 0, total = 0;
    std::size_t batches = 0;  // batches begun so far (a run may have several)
  };
  void Begin(const std::string& label, const std::string& unit, std::size_t total);
  void Update(std::size_t done);
  State Get() const;

 private:
  mutable std::mutex mutex_;
  State state_;
};

class ProgressMeter {
 public:
  enum class Style { kInPlace, kLog };
  static constexpr double kQuietSeconds = 2.0;         // nothing before this
  static constexpr double kIntervalSeconds = 0.5;      // in place: twice a second
  static constexpr double kLogIntervalSeconds = 10.0;  // a log: every 10 s

  // A null stream or enabled = false prints nothing.
  ProgressMeter(std::string label, std::size_t total, bool enabled, std::FILE* stream,
                std::string unit = "trials", Style style = Style::kInPlace);

  // Rewrites the line if the rules above allow it.
  void Update(std::size_t done, double elapsed_s);
  // Writes the final state ("finished in" or "stopped after") and a newline,
  // only if Update printed anything.
  void Finish(std::size_t done, double elapsed_s);

  bool printed() const { return printed_width_ > 0; }

 private:
  void Print(const std::string& line, bool final_line);

  std::string label_;
  std::string unit_;
  std::size_t total_;
  std::FILE* stream_;
  Style style_;
  double last_print_s_ = -1.0;
  std::size_t printed_width_ = 0;  // length of the last line, to blank its tail
};

}  // namespace vahf::experiment
