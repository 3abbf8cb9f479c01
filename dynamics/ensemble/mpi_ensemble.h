#pragma once
// An ensemble over MPI ranks: the same command under `mpirun -np N` (docs/ensembles.md §5). All
// MPI code of frictionlab is in mpi_ensemble.cpp, compiled with MPI only when the build found it
// (FRICTIONLAB_WITH_MPI); without, a job under mpirun with more than one rank is refused.
//
// MPI is initialised only when the process was started by an MPI launcher (the environment has
// OMPI_COMM_WORLD_SIZE, PMI_SIZE or PMIX_RANK), so `frictionlab ensemble` alone never touches MPI.
//
// Rank 0 coordinates and writes: it holds the session (runs.csv, trajectories, progress), hands
// out tasks one at a time to the ranks that ask (dynamic load balancing), receives every finished
// run, and also runs tasks on its own worker threads (--threads, default 1 under MPI: one rank per
// core is the usual layout). Ranks > 0 read the study themselves (the folder must be shared), check
// its hash against rank 0's, then ask for a task, run it, send each run's row (and trajectory) as
// it finishes, and ask again. The coordinator polls (MPI_Iprobe, 1 ms sleeps) rather than blocking,
// so it costs no core of its own.
//
// A rank that dies: under OpenMPI the launcher then aborts the whole job. Every run already
// received is in runs.csv (flushed per row); the runs in flight are lost, and `--resume` redoes
// exactly those.

#include "dynamics/ensemble/ensemble_job.h"

namespace frictionlab::dynamics::ensemble {

/// Whether an MPI launcher started this process (see the header comment).
[[nodiscard]] bool launched_by_mpi();
/// The number of ranks the launcher started, from the environment (1 if none).
[[nodiscard]] int launcher_world_size();
/// This process's rank, from the launcher's environment (0 if no launcher started it).
[[nodiscard]] int launcher_rank();
/// Whether this build has MPI.
[[nodiscard]] bool mpi_available();

/// The job over the ranks (every rank calls it). Without MPI in the build: the plain job for a
/// single rank, std::invalid_argument for more.
[[nodiscard]] JobOutcome run_ensemble_job_mpi(const JobOptions& options);

}  // namespace frictionlab::dynamics::ensemble
