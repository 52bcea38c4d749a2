// launched_ranks.h for a build without MPI.
#include <cstdlib>

#include "vahf/core/error.h"
#include "vahf/experiment/launched_ranks.h"

namespace vahf::experiment {

std::unique_ptr<Ranks> JoinLaunchedRanks(int*, char***) {
  const std::string launched = LauncherVariable();
  if (launched.empty()) return nullptr;
  // A job of one process is this process alone (a script run inside a job).
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"})
    if (const char* size = std::getenv(name); size && std::atoi(size) == 1)
      return nullptr;
  throw InputError("environment", "", launched,
                   "this vahf was built without MPI, so each rank would run the whole "
                   "experiment alone: install libopenmpi-dev (tools/setup) and build "
                   "again, or run it without mpirun");
}

}  // namespace vahf::experiment
