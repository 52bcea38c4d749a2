// The three tiers of what can go wrong, and the vahf command's exit status for
// each (docs/design.md, "Errors"; docs/style.md):
//
// 1. Input error: the user's input (a file, a value in it, a command-line
//    option) breaks a rule. Throw vahf::InputError naming the file, where in
//    it, the value and the rule; the command prints it on one line and exits
//    kExitInputError (2). A layer that checks a value without knowing its file
//    (geometry, tessellation, visibility, a contact model) throws it with an
//    empty file and its own `where`; the reader that knows the file catches
//    exactly that class and throws again with the file and JSON pointer.
// 2. Computation failure: the input is valid, but a computation cannot give a
//    result (a statistic of too few values or of values that do not vary, an
//    argument outside a function's domain, a library, program or system call
//    refusing). Throw vahf::ComputationError with its Reason; the command
//    prints it and exits kExitComputationFailure (1). A caller that can go on
//    without the result catches ComputationError and tests reason(), or
//    catches a subclass (report::PlotError); never a standard exception.
// 3. Internal check: an invariant the code itself guarantees fails. That is a
//    bug, not input: VAHF_CHECK aborts with file and line. A host that must
//    not end (the Python module, python/) calls ThrowOnInternalCheck() once:
//    a failed check then throws InternalError instead; the command never does.
//
// Not an error: experiment::Interrupted (experiment/interrupt.h) reports a
// stop the user asked for (Ctrl-C); the command exits kExitInterrupted (130,
// 128 + SIGINT, as a shell reports a process ended by SIGINT).
#pragma once

#include <stdexcept>
#include <string>

namespace vahf {

// Exit status of the vahf command when its input is bad.
inline constexpr int kExitInputError = 2;
// Exit status when a computation failed on valid input (and when `vahf trial`'s
// trial ended other than completed).
inline constexpr int kExitComputationFailure = 1;
// Exit status when the user stopped a run.
inline constexpr int kExitInterrupted = 130;

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

// A computation that cannot give a result on valid input. what() is the
// message as given: the function, the value and why, e.g. "WelchTTest: a has 1
// values: needs at least 2".
class ComputationError : public std::runtime_error {
 public:
  enum class Reason {
    kTooFewValues,  // fewer values than the quantity needs (a mean of none)
    kZeroVariance,  // the values do not vary: a t statistic or slope is undefined
    kOutOfDomain,   // an argument outside the function's domain (NaN, p > 1)
    kRefused,       // a library, program or system call refused or failed
  };

  ComputationError(Reason reason, const std::string& message)
      : std::runtime_error(message), reason_(reason) {}

  Reason reason() const { return reason_; }

 private:
  Reason reason_;
};

// A failed internal check (VAHF_CHECK), thrown instead of aborting once
// ThrowOnInternalCheck() was called. what() reads "internal error (a bug):
// FILE:LINE: check 'CONDITION' failed: MESSAGE".
class InternalError : public std::logic_error {
 public:
  InternalError(std::string condition, std::string file, int line, std::string message);

  const std::string& condition() const { return condition_; }
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& message() const { return message_; }

 private:
  std::string condition_, file_;
  int line_;
  std::string message_;
};

// Aborts with file and line when an internal invariant fails: a bug, not input.
// After ThrowOnInternalCheck(), throws InternalError instead.
[[noreturn]] void CheckFailed(const char* condition, const char* file, int line,
                              const std::string& message);

// From now on, in this process, a failed check throws InternalError. For a
// host that must outlive a bug (the Python module); the command never calls it.
// A check that fails where no exception may leave (a destructor, a noexcept
// function) still ends the process, by std::terminate.
void ThrowOnInternalCheck();

}  // namespace vahf

#define VAHF_CHECK(condition, message)                                                \
  do {                                                                                \
    if (!(condition)) ::vahf::CheckFailed(#condition, __FILE__, __LINE__, (message)); \
  } while (false)
