#include "vahf/experiment/progress.h"

#include <fmt/format.h>
#include <unistd.h>

#include <cmath>
#include <utility>

namespace vahf::experiment {
namespace {

std::string Duration(double seconds) {
  const double s = std::ceil(seconds);
  if (s < 120) return fmt::format("{} s", s);
  if (s < 120 * 60) return fmt::format("{} min", std::ceil(s / 60));
  return fmt::format("{:.1f} h", s / 3600);
}

std::string Prefix(const std::string& label, std::size_t done, std::size_t total,
                   double elapsed_s, const std::string& unit) {
  const double rate = elapsed_s > 0 ? static_cast<double>(done) / elapsed_s : 0.0;
  return fmt::format("{}{}/{} {}, {:.1f} {}/s", label.empty() ? "" : label + ": ", done,
                     total, unit, rate, unit);
}

}  // namespace

std::string FormatProgress(const std::string& label, std::size_t done, std::size_t total,
                           double elapsed_s, const std::string& unit) {
  std::string line = Prefix(label, done, total, elapsed_s, unit);
  if (done == 0 || elapsed_s <= 0) return line + ", time left unknown";
  const double left_s =
      static_cast<double>(total - done) * elapsed_s / static_cast<double>(done);
  return line + ", about " + Duration(left_s) + " left";
}

bool IsTerminal(std::FILE* stream) {
  return stream != nullptr && ::isatty(::fileno(stream)) == 1;
}

void ProgressSink::Begin(const std::string& label, const std::string& unit,
                         std::size_t total) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.label = label;
  state_.unit = unit;
  state_.total = total;
  state_.done = 0;
  ++state_.batches;
}

void ProgressSink::Update(std::size_t done) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.done = done;
}

ProgressSink::State ProgressSink::Get() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

ProgressMeter::ProgressMeter(std::string label, std::size_t total, bool enabled,
                             std::FILE* stream, std::string unit, Style style)
    : label_(std::move(label)),
      unit_(std::move(unit)),
      total_(total),
      stream_(enabled ? stream : nullptr),
      style_(style) {}

void ProgressMeter::Update(std::size_t done, double elapsed_s) {
  if (stream_ == nullptr || elapsed_s <= kQuietSeconds) return;
  const double interval = style_ == Style::kLog ? kLogIntervalSeconds : kIntervalSeconds;
  if (last_print_s_ >= 0 && elapsed_s - last_print_s_ < interval) return;
  last_print_s_ = elapsed_s;
  Print(FormatProgress(label_, done, total_, elapsed_s, unit_), false);
}

void ProgressMeter::Finish(std::size_t done, double elapsed_s) {
  if (!printed()) return;
  const std::string how = done == total_ ? "finished in " : "stopped after ";
  Print(Prefix(label_, done, total_, elapsed_s, unit_) + ", " + how + Duration(elapsed_s),
        true);
}

void ProgressMeter::Print(const std::string& line, bool final_line) {
  if (style_ == Style::kLog) {
    std::fprintf(stream_, "%s\n", line.c_str());
    std::fflush(stream_);
    printed_width_ = line.size();
    return;
  }
  // Blank whatever a longer previous line left behind.
  const std::size_t pad = printed_width_ > line.size() ? printed_width_ - line.size() : 0;
  std::fprintf(stream_, "\r%s%*s%s", line.c_str(), static_cast<int>(pad), "",
               final_line ? "\n" : "");
  std::fflush(stream_);
  printed_width_ = line.size();
}

}  // namespace vahf::experiment
