// launched_ranks.h with MPI (Open MPI from Debian: libopenmpi-dev).
#include <fmt/format.h>
#include <mpi.h>

#include <climits>
#include <cstdint>
#include <cstdlib>

#include "vahf/core/error.h"
#include "vahf/experiment/launched_ranks.h"

namespace vahf::experiment {
namespace {

// An MPI call that did not succeed, as a ComputationError naming it.
void Check(int code, const char* call) {
  if (code == MPI_SUCCESS) return;
  char text[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, text, &length);
  throw ComputationError(ComputationError::Reason::kRefused,
                         fmt::format("{}: {}", call, std::string(text, length)));
}

// MPI_COMM_WORLD, from MPI_Init_thread to MPI_Finalize.
class MpiRanks : public Ranks {
 public:
  MpiRanks(int* argc, char*** argv) {
    int provided = 0;
    Check(MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
    try {
      // Errors come back as codes, turned into ComputationErrors, instead of
      // aborting the job without a word.
      Check(MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN),
            "MPI_Comm_set_errhandler");
      Check(MPI_Comm_rank(MPI_COMM_WORLD, &rank_), "MPI_Comm_rank");
      Check(MPI_Comm_size(MPI_COMM_WORLD, &size_), "MPI_Comm_size");
      if (provided < MPI_THREAD_FUNNELED)
        throw ComputationError(ComputationError::Reason::kRefused,
                               "MPI_Init_thread: this MPI cannot be used from a process "
                               "with several threads (MPI_THREAD_FUNNELED)");
      CheckTheLauncherAgrees();
    } catch (...) {
      MPI_Finalize();
      throw;
    }
  }
  ~MpiRanks() override { MPI_Finalize(); }

  [[noreturn]] void Abort(int status) const override {
    MPI_Abort(MPI_COMM_WORLD, status);
    std::_Exit(status);  // MPI_Abort does not return; if it did, end this rank
  }

  int rank() const override { return rank_; }
  int size() const override { return size_; }

  std::vector<std::string> AllGather(const std::string& mine) const override {
    const auto n = static_cast<std::size_t>(size_);
    std::vector<long long> sizes(n);
    long long my_size = static_cast<long long>(mine.size());
    Check(MPI_Allgather(&my_size, 1, MPI_LONG_LONG, sizes.data(), 1, MPI_LONG_LONG,
                        MPI_COMM_WORLD),
          "MPI_Allgather");
    // MPI_Allgatherv counts and places bytes with int.
    std::vector<int> counts(n), offsets(n);
    long long total = 0;
    for (std::size_t r = 0; r < n; ++r) {
      if (total + sizes[r] > INT_MAX)
        throw ComputationError(
            ComputationError::Reason::kRefused,
            fmt::format("gathering a batch's results: {} bytes and more, over the {} "
                        "bytes one MPI_Allgatherv can carry; use fewer cycles per run",
                        total + sizes[r], INT_MAX));
      counts[r] = static_cast<int>(sizes[r]);
      offsets[r] = static_cast<int>(total);
      total += sizes[r];
    }
    std::string all(static_cast<std::size_t>(total), '\0');
    Check(MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPI_BYTE, all.data(),
                         counts.data(), offsets.data(), MPI_BYTE, MPI_COMM_WORLD),
          "MPI_Allgatherv");
    std::vector<std::string> out(n);
    for (std::size_t r = 0; r < n; ++r)
      out[r] = all.substr(static_cast<std::size_t>(offsets[r]),
                          static_cast<std::size_t>(counts[r]));
    return out;
  }

 private:
  // A launcher this MPI cannot talk to (MPICH's hydra starting Open MPI, a
  // PMI Slurm lacks) leaves every process a job of its own: each would run
  // the whole experiment and write the same output. The size the launcher
  // states must be MPI's.
  void CheckTheLauncherAgrees() const {
    for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
      const char* value = std::getenv(name);
      if (!value) continue;
      if (std::atoi(value) != size_)
        throw InputError(
            "environment", "", std::string(name) + "=" + value,
            fmt::format("the launcher started {} processes but MPI_Init gave "
                        "a job of {}: this MPI cannot talk to that launcher "
                        "(use the mpirun of the MPI vahf was built with)",
                        value, size_));
    }
  }

  int rank_ = 0, size_ = 1;
};

}  // namespace

std::unique_ptr<Ranks> JoinLaunchedRanks(int* argc, char*** argv) {
  if (LauncherVariable().empty()) return nullptr;
  return std::make_unique<MpiRanks>(argc, argv);
}

}  // namespace vahf::experiment
