// All of frictionlab's MPI code (dynamics/ensemble/mpi_ensemble.h).
#include "dynamics/ensemble/mpi_ensemble.h"

#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "dynamics/ensemble/thread_pool.h"

#ifdef FRICTIONLAB_WITH_MPI
#include <mpi.h>
#endif

namespace frictionlab::dynamics::ensemble {
namespace {

int environment_integer(const char* name) {
  const char* v = std::getenv(name);
  if (!v || !*v) return -1;
  char* end = nullptr;
  const long x = std::strtol(v, &end, 10);
  return end && *end == '\0' ? static_cast<int>(x) : -1;
}

}  // namespace

bool launched_by_mpi() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
}

int launcher_world_size() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    const int n = environment_integer(name);
    if (n > 0) return n;
  }
  return 1;
}

int launcher_rank() {
  for (const char* name : {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK"}) {
    const int r = environment_integer(name);
    if (r >= 0) return r;
  }
  return 0;
}

#ifndef FRICTIONLAB_WITH_MPI

bool mpi_available() { return false; }

JobOutcome run_ensemble_job_mpi(const JobOptions& options) {
  const int n = launcher_world_size();
  if (n > 1)
    throw std::invalid_argument("mpirun started " + std::to_string(n) +
                                " ranks, but this frictionlab was built without MPI: each would run the whole "
                                "ensemble into the same folder; rebuild with libopenmpi-dev, or run without mpirun");
  return run_ensemble_job_on_threads(options);
}

#else

bool mpi_available() { return true; }

namespace {

enum Tag : int { kRequest = 1, kTask = 2, kStop = 3, kRow = 4, kTrajectory = 5, kBye = 6 };
constexpr auto kPoll = std::chrono::milliseconds(1);

// MPI_Init on construction, MPI_Finalize on destruction (after a barrier that sleeps between
// tests rather than spinning: a rank that is done waits without taking a core from the others).
class MpiSession {
 public:
  MpiSession() {
    int provided = 0;
    MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
    if (provided < MPI_THREAD_FUNNELED) {
      MPI_Finalize();
      throw std::runtime_error("the MPI library does not allow worker threads beside the thread that calls MPI "
                               "(MPI_THREAD_FUNNELED)");
    }
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
    MPI_Comm_size(MPI_COMM_WORLD, &size_);
  }
  ~MpiSession() {
    polite_barrier();
    MPI_Finalize();
  }
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  [[nodiscard]] int rank() const { return rank_; }
  [[nodiscard]] int size() const { return size_; }

  /// Whether every rank says `ok`.
  [[nodiscard]] bool all(bool ok) const {
    int mine = ok ? 1 : 0;
    int every = 0;
    MPI_Allreduce(&mine, &every, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
    return every == 1;
  }

  static void polite_barrier() {
    MPI_Request request;
    MPI_Ibarrier(MPI_COMM_WORLD, &request);
    int done = 0;
    for (;;) {
      MPI_Test(&request, &done, MPI_STATUS_IGNORE);
      if (done) return;
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
  }

 private:
  int rank_ = 0;
  int size_ = 1;
};

// A rank > 0 that could not go on because another rank failed (that rank reports it).
JobOutcome quiet_worker_outcome() {
  JobOutcome o;
  o.writer = false;
  o.quiet_failure = true;
  return o;
}

void send_text(const std::string& s, int to, int tag) {
  MPI_Send(s.data(), static_cast<int>(s.size()), MPI_CHAR, to, tag, MPI_COMM_WORLD);
}

std::string receive_text(int from, int tag, MPI_Status* status = nullptr) {
  MPI_Status st;
  MPI_Probe(from, tag, MPI_COMM_WORLD, &st);
  int n = 0;
  MPI_Get_count(&st, MPI_CHAR, &n);
  std::string s(static_cast<std::size_t>(n), '\0');
  MPI_Recv(s.data(), n, MPI_CHAR, st.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  if (status) *status = st;
  return s;
}

// A trajectory as one array: its length, then each column.
std::vector<double> pack(const DecimatedTrajectory& t) {
  std::vector<double> out{static_cast<double>(t.size())};
  for (const auto* c : t.columns()) out.insert(out.end(), c->begin(), c->end());
  return out;
}

DecimatedTrajectory unpack(const std::vector<double>& data) {
  DecimatedTrajectory t;
  if (data.empty()) return t;
  const auto n = static_cast<std::size_t>(data[0]);
  std::size_t pos = 1;
  for (auto* c : t.columns()) {
    c->assign(data.begin() + static_cast<long>(pos), data.begin() + static_cast<long>(pos + n));
    pos += n;
  }
  return t;
}

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Ranks > 0: ask, run, send, ask again. Returns the seconds spent waiting for answers.
double worker_loop(const EnsemblePlan& plan, const JobOptions& options) {
  ExecuteOptions exec;
  exec.trajectories = options.trajectories;
  exec.cancel = options.cancel;
  double waited = 0.0;
  for (;;) {
    const auto asked = Clock::now();
    MPI_Send(nullptr, 0, MPI_LONG, 0, kRequest, MPI_COMM_WORLD);
    MPI_Status st;
    MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &st);
    waited += seconds_since(asked);
    if (st.MPI_TAG == kStop) {
      MPI_Recv(nullptr, 0, MPI_LONG, 0, kStop, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return waited;
    }
    int n = 0;
    MPI_Get_count(&st, MPI_LONG, &n);
    std::vector<long> message(static_cast<std::size_t>(n));
    MPI_Recv(message.data(), n, MPI_LONG, 0, kTask, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    TaskOrder order;
    order.task = plan.task(message.at(0));
    order.todo.assign(message.begin() + 1, message.end());
    const bool completed = execute_task(plan, order, exec, [&](FinishedRun&& r) {
      send_text(to_csv_row(r.record), 0, kRow);
      if (options.trajectories) {
        const std::vector<double> data = pack(r.trajectory);
        MPI_Send(data.data(), static_cast<int>(data.size()), MPI_DOUBLE, 0, kTrajectory, MPI_COMM_WORLD);
      }
    });
    if (!completed) {
      MPI_Send(nullptr, 0, MPI_LONG, 0, kBye, MPI_COMM_WORLD);
      return waited;
    }
  }
}

// Rank 0: serves the other ranks from the session's queue and records what they send, while its
// own worker threads take tasks from the same queue. Counts what serving costs.
void coordinate(EnsembleSession& session, int ranks, int local_threads, const JobOptions& options,
                CoordinationCost& cost) {
  const std::size_t keys = session.plan().study().vary.size();
  std::vector<std::thread> local;
  std::atomic<int> local_running{local_threads};
  std::exception_ptr failure;
  std::mutex failure_mutex;
  for (int i = 0; i < local_threads; ++i)
    local.emplace_back([&] {
      try {
        work_on_session(session);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failure_mutex);
        if (!failure) failure = std::current_exception();
        session.halt();
      }
      --local_running;
    });

  int active = ranks - 1;
  while (active > 0 || local_running.load() > 0) {
    if (options.cancel && options.cancel->load()) session.halt();
    int pending = 0;
    MPI_Status st;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &pending, &st);
    if (!pending) {
      std::this_thread::sleep_for(kPoll);
      continue;
    }
    const auto busy_from = Clock::now();
    const int from = st.MPI_SOURCE;
    switch (st.MPI_TAG) {
      case kRequest: {
        MPI_Recv(nullptr, 0, MPI_LONG, from, kRequest, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        const auto order = session.halt_flag().load() ? std::nullopt : session.queue().next();
        if (!order) {
          MPI_Send(nullptr, 0, MPI_LONG, from, kStop, MPI_COMM_WORLD);
          --active;
          break;
        }
        std::vector<long> message{order->task.index};
        message.insert(message.end(), order->todo.begin(), order->todo.end());
        MPI_Send(message.data(), static_cast<int>(message.size()), MPI_LONG, from, kTask, MPI_COMM_WORLD);
        ++cost.tasks_sent;
        break;
      }
      case kRow: {
        const std::string row = receive_text(from, kRow);
        FinishedRun run;
        run.record = parse_run_row(std::string_view(row).substr(0, row.size() - 1), keys, session.plan().model(),
                                   session.plan().shadow_laws().size());
        if (options.trajectories) {
          MPI_Status ts;
          MPI_Probe(from, kTrajectory, MPI_COMM_WORLD, &ts);
          int n = 0;
          MPI_Get_count(&ts, MPI_DOUBLE, &n);
          std::vector<double> data(static_cast<std::size_t>(n));
          MPI_Recv(data.data(), n, MPI_DOUBLE, from, kTrajectory, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
          run.trajectory = unpack(data);
        }
        session.record(std::move(run));
        ++cost.runs_received;
        break;
      }
      case kBye:
        MPI_Recv(nullptr, 0, MPI_LONG, from, kBye, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
        --active;
        break;
      default: {
        // Not ours: take it off the queue so the loop does not spin on it.
        int n = 0;
        MPI_Get_count(&st, MPI_BYTE, &n);
        std::vector<char> junk(static_cast<std::size_t>(std::max(n, 0)));
        MPI_Recv(junk.data(), n, MPI_BYTE, from, st.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      }
    }
    cost.busy += seconds_since(busy_from);
  }
  for (auto& t : local) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace

JobOutcome run_ensemble_job_mpi(const JobOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  MpiSession mpi;
  const bool root = mpi.rank() == 0;

  // Every rank reads the study; rank 0 reports a failure, the others go quietly.
  std::unique_ptr<EnsemblePlan> plan;
  std::string error;
  try {
    plan = std::make_unique<EnsemblePlan>(EnsemblePlan::make(read_study(options.study)));
  } catch (const std::exception& e) {
    error = e.what();
  }
  if (!mpi.all(error.empty())) {
    if (root) throw std::invalid_argument(error.empty() ? "another MPI rank could not read the study" : error);
    return quiet_worker_outcome();
  }
  // The same study on every rank (a shared folder, the same files).
  char hash[17] = {};
  if (root) plan->hash().copy(hash, 16);
  MPI_Bcast(hash, 17, MPI_CHAR, 0, MPI_COMM_WORLD);
  if (!mpi.all(plan->hash() == hash)) {
    if (root)
      throw std::invalid_argument("the MPI ranks read different study or scenario files (their hashes differ): "
                                  "run every rank on one shared folder");
    return quiet_worker_outcome();
  }

  JobOutcome outcome;
  outcome.ranks = mpi.size();
  outcome.threads = options.threads > 0 ? options.threads : 1;
  if (!root) {
    outcome.writer = false;
    double waited = worker_loop(*plan, options);
    MPI_Reduce(&waited, nullptr, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
    outcome.interrupted = options.cancel && options.cancel->load();
    outcome.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return outcome;
  }

  std::unique_ptr<EnsembleSession> session;
  try {
    SessionOptions so;
    so.out = options.out;
    so.resume = options.resume;
    so.trajectories = options.trajectories;
    so.log = options.log;
    so.live = options.live;
    so.command = options.command;
    so.on_progress = options.on_progress;
    session = std::make_unique<EnsembleSession>(*plan, so);
  } catch (...) {
    // Tell the workers to stop before their first task.
    for (int done = 1; done < mpi.size(); ++done) {
      MPI_Status st;
      MPI_Recv(nullptr, 0, MPI_LONG, MPI_ANY_SOURCE, kRequest, MPI_COMM_WORLD, &st);
      MPI_Send(nullptr, 0, MPI_LONG, st.MPI_SOURCE, kStop, MPI_COMM_WORLD);
    }
    double none = 0.0;
    double waited = 0.0;
    MPI_Reduce(&none, &waited, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);  // as the workers do
    throw;
  }
  coordinate(*session, mpi.size(), outcome.threads, options, outcome.coordination);
  double none = 0.0;
  MPI_Reduce(&none, &outcome.coordination.worker_wait, 1, MPI_DOUBLE, MPI_SUM, 0, MPI_COMM_WORLD);
  outcome.interrupted = options.cancel && options.cancel->load();
  outcome = finish_job(*session, options, outcome);
  outcome.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return outcome;
}

#endif

}  // namespace frictionlab::dynamics::ensemble
