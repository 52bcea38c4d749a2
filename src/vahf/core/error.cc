#include "vahf/core/error.h"

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace vahf {
namespace {

std::atomic<bool> throw_on_check{false};

std::string Compose(const std::string& file, const std::string& where,
                    const std::string& value, const std::string& rule) {
  std::string out = file.empty() ? std::string("<input>") : file;
  if (!where.empty()) out += ": " + where;
  if (!value.empty()) out += " = " + value;
  return out + ": " + rule;
}

}  // namespace

InputError::InputError(std::string file, std::string where, std::string value,
                       std::string rule)
    : std::runtime_error(Compose(file, where, value, rule)),
      file_(std::move(file)),
      where_(std::move(where)),
      value_(std::move(value)),
      rule_(std::move(rule)) {}

InternalError::InternalError(std::string condition, std::string file, int line,
                             std::string message)
    : std::logic_error("internal error (a bug): " + file + ":" + std::to_string(line) +
                       ": check '" + condition + "' failed: " + message),
      condition_(std::move(condition)),
      file_(std::move(file)),
      line_(line),
      message_(std::move(message)) {}

void ThrowOnInternalCheck() { throw_on_check.store(true); }

void CheckFailed(const char* condition, const char* file, int line,
                 const std::string& message) {
  if (throw_on_check.load()) throw InternalError(condition, file, line, message);
  std::fprintf(stderr, "vahf: internal error (a bug): %s:%d: check '%s' failed: %s\n",
               file, line, condition, message.c_str());
  std::abort();
}

}  // namespace vahf
