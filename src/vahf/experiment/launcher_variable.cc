// LauncherVariable (launched_ranks.h), shared by both builds.
#include <cstdlib>

#include "vahf/experiment/launched_ranks.h"

namespace vahf::experiment {

std::string LauncherVariable() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMIX_RANK", "PMI_SIZE"})
    if (const char* value = std::getenv(name)) return std::string(name) + "=" + value;
  return "";
}

}  // namespace vahf::experiment
