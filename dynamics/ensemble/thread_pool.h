#pragma once
// The worker threads of an ensemble on one process: each takes the next task of the session's
// queue when it has finished one (dynamic load balancing) and records each run as it finishes.
// The calling thread waits and watches `cancel` (Ctrl-C: the runs in flight stop between steps
// and are not recorded; they will be redone by --resume).

#include <atomic>

#include "dynamics/ensemble/ensemble_session.h"

namespace frictionlab::dynamics::ensemble {

/// Worker threads for `threads` (0: one per core, std::thread::hardware_concurrency()).
[[nodiscard]] int thread_count(int threads);

/// Runs the session's queue on `threads` worker threads (> 0). Returns when the queue is empty or
/// the job was halted (cancel raised, or the output failed). An exception escaping a worker (not a
/// run's failure: those are records) halts the others and is rethrown here.
void run_on_threads(EnsembleSession& session, int threads, const std::atomic<bool>* cancel);

/// One worker's loop: tasks from the session's queue until it is empty or halted. Exposed for the
/// MPI coordinator's local workers.
void work_on_session(EnsembleSession& session);

}  // namespace frictionlab::dynamics::ensemble
