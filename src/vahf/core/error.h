// Errors a user can cause (bad input files, bad options) and their exit code.
//
// Two tiers: a user's bad input throws vahf::InputError, which the
// command reports in one line and exits with kExitInputError; a broken internal
// invariant is a bug and aborts loudly through VAHF_CHECK.
#pragma once

#include <stdexcept>
#include <string>

namespace vahf {

// Exit status of the vahf command when its input is bad.
inline constexpr int kExitInputError = 2;

// One error in a user's input: which file, where in it (a JSON pointer such as
// "/parts/2/profile/3", or "line 7" for CSV), the offending value, and the rule
// it breaks. what() reads "FILE: WHERE = VALUE: RULE".
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, std::string where, std::string value, std::string rule);

  const std::string& file() const { return file_; }
  const std::string& where() const { return where_; }
  const std::string& value() const { return value_; }
  const std::string& rule() const { return rule_; }

 private:
  std::string file_, where_, value_, rule_;
};

// Aborts with file and line when an internal invariant fails: a bug, not input.
[[noreturn]] void CheckFailed(const char* condition, const char* file, int line,
                              const std::string& message);

}  // namespace vahf

#define VAHF_CHECK(condition, message)                                                \
  do {                                                                                \
    if (!(condition)) ::vahf::CheckFailed(#condition, __FILE__, __LINE__, (message)); \
  } while (false)
