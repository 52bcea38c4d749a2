#include "vahf/experiment/ranks.h"

#include <atomic>

#include "vahf/core/byte_fields.h"
#include "vahf/core/error.h"
#include "vahf/experiment/interrupt.h"

namespace vahf::experiment {
namespace {

// The classes an encoded exception can be, one byte each.
enum Tag : std::uint64_t { kInput = 1, kComputation = 2, kInterrupted = 3, kOther = 4 };

}  // namespace

std::string EncodeException(const std::exception_ptr& error) {
  ByteWriter w;
  try {
    std::rethrow_exception(error);
  } catch (const InputError& e) {
    w.U64(kInput);
    w.Str(e.file());
    w.Str(e.where());
    w.Str(e.value());
    w.Str(e.rule());
  } catch (const ComputationError& e) {
    w.U64(kComputation);
    w.U64(static_cast<std::uint64_t>(e.reason()));
    w.Str(e.what());
  } catch (const Interrupted& e) {
    w.U64(kInterrupted);
    w.Str(e.what());
  } catch (const std::exception& e) {
    w.U64(kOther);
    w.Str(e.what());
  }
  return w.Take();
}

namespace {
std::atomic<bool> agreed{false};
}  // namespace

bool ErrorAgreedByAllRanks() { return agreed.load(); }

void ThrowAgreed(const std::exception_ptr& error) {
  agreed.store(true);
  std::rethrow_exception(error);
}

void ThrowEncodedException(const std::string& bytes) {
  agreed.store(true);
  ByteReader r(bytes);
  switch (r.U64()) {
    case kInput: {
      std::string file = r.Str(), where = r.Str(), value = r.Str();
      throw InputError(std::move(file), std::move(where), std::move(value), r.Str());
    }
    case kComputation: {
      const std::uint64_t reason = r.U64();
      throw ComputationError(
          reason <= static_cast<std::uint64_t>(ComputationError::Reason::kRefused)
              ? static_cast<ComputationError::Reason>(reason)
              : ComputationError::Reason::kRefused,
          r.Str());
    }
    case kInterrupted:
      throw Interrupted(r.Str());
    case kOther:  // a library's exception: a failure of the computation all the same
      throw ComputationError(ComputationError::Reason::kRefused, r.Str());
    default:
      throw ComputationError(ComputationError::Reason::kRefused,
                             "an error sent between ranks has an unknown class");
  }
}

void AllAgree(const Ranks* ranks, const std::function<void()>& step) {
  if (!ranks) return step();
  std::string mine;  // empty: the step succeeded here
  try {
    step();
  } catch (const std::exception&) {
    mine = EncodeException(std::current_exception());
  }
  for (const std::string& error : ranks->AllGather(mine))
    if (!error.empty()) ThrowEncodedException(error);
}

}  // namespace vahf::experiment
