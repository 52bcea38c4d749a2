// The processes one run is spread over: MPI ranks (docs/reproducibility.md,
// "Many machines: MPI"). Every rank runs the same command on the same inputs,
// so it takes the same control flow; RunIndexed (runner.h) gives each rank
// its share of a batch's indices and gathers every result on every rank, in
// index order, so what follows a batch (a calibration's next point, a
// report) is the same bits on every rank and for any rank count.
//
// This interface knows nothing of MPI: the vahf command implements it with
// MPI (mpi_ranks.h), the tests with threads standing in for processes.
#pragma once

#include <exception>
#include <functional>
#include <string>
#include <vector>

namespace vahf::experiment {

class Ranks {
 public:
  virtual ~Ranks() = default;
  virtual int rank() const = 0;  // this process: 0 to size() - 1
  virtual int size() const = 0;  // >= 1
  // Every rank's `mine`, indexed by rank, on every rank. Collective: every
  // rank calls it, the same number of times in the same order. A transport
  // that fails is a ComputationError (kRefused).
  virtual std::vector<std::string> AllGather(const std::string& mine) const = 0;
  // Ends every rank at once with `status` (MPI_Abort): for an error only this
  // rank met, after which the others would wait for it forever.
  [[noreturn]] virtual void Abort(int status) const = 0;
};

// An exception of the kinds a run throws (vahf::InputError,
// vahf::ComputationError, Interrupted) as bytes, and thrown again from them on
// another rank as the same tier (core/error.h: a subclass comes back as its
// base), with its fields and message, so every rank stops with the error one
// of them met. Any other std::exception (a library's, or std::bad_alloc)
// comes back as a ComputationError (kRefused) with its message: the
// command's exit status for it is the same.
std::string EncodeException(const std::exception_ptr& error);
[[noreturn]] void ThrowEncodedException(const std::string& bytes);

// True once this process threw an error every rank throws alike
// (ThrowEncodedException, AllAgree): the ranks can end normally. Any other
// error, with several ranks, is this rank's alone: the command ends the job
// with Ranks::Abort.
bool ErrorAgreedByAllRanks();

// Throws `error`, which every rank throws alike (each rank has made it from
// the same gathered bytes), as agreed.
[[noreturn]] void ThrowAgreed(const std::exception_ptr& error);

// Runs `step` on every rank, then agrees: if it threw on any rank, every
// rank throws the error of the lowest such rank. For a step only some ranks
// take (rank 0 checks the output directory), so that a refusal there stops
// every rank instead of leaving the others waiting in their next AllGather.
// Without ranks (null: one process) it runs `step` alone.
void AllAgree(const Ranks* ranks, const std::function<void()>& step);

}  // namespace vahf::experiment
