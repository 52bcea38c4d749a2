// The ranks of the MPI job this process was started in (docs/reproducibility.md,
// "Many machines: MPI"). Two implementations, one per build: with MPI
// (mpi_ranks.cc, when CMake finds it) and without (single_rank.cc); only the
// vahf command links either, so the library and its tests never start MPI.
#pragma once

#include <memory>
#include <string>

#include "vahf/experiment/ranks.h"

namespace vahf::experiment {

// The launcher variable that says this process is one of a job's ranks
// (OMPI_COMM_WORLD_SIZE from Open MPI's mpirun, PMIX_RANK from a PMIx launcher
// such as Slurm's srun --mpi=pmix, PMI_SIZE from MPICH's or a PMI-2 one), as
// NAME=VALUE; empty when no launcher started it.
std::string LauncherVariable();

// Joins the job: MPI_Init_thread (MPI_THREAD_FUNNELED: only the calling
// thread talks to MPI, between batches) and MPI_COMM_WORLD as Ranks; the
// object's destructor ends MPI. Null when LauncherVariable() is empty: a
// process started alone never starts MPI. A launcher that states another
// size than MPI gives is an InputError (this MPI cannot talk to it). Without
// MPI in the build, a process launched among several is an InputError naming
// the variable (each rank would run the whole experiment alone), one
// launched alone is null. Call it once per process.
std::unique_ptr<Ranks> JoinLaunchedRanks(int* argc, char*** argv);

}  // namespace vahf::experiment
