#include "dynamics/ensemble/thread_pool.h"

#include <chrono>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace frictionlab::dynamics::ensemble {

int thread_count(int threads) {
  if (threads > 0) return threads;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw > 0 ? static_cast<int>(hw) : 1;
}

void work_on_session(EnsembleSession& session) {
  ExecuteOptions options;
  options.trajectories = session.options().trajectories;
  options.cancel = &session.halt_flag();
  while (!session.halt_flag().load()) {
    const auto order = session.queue().next();
    if (!order) return;
    if (!execute_task(session.plan(), *order, options, [&](FinishedRun&& r) { session.record(std::move(r)); })) return;
  }
}

void run_on_threads(EnsembleSession& session, int threads, const std::atomic<bool>* cancel) {
  std::mutex mutex;
  std::condition_variable finished;
  int running = threads;
  std::exception_ptr failure;
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(threads));
  for (int i = 0; i < threads; ++i)
    pool.emplace_back([&] {
      try {
        work_on_session(session);
      } catch (...) {
        const std::lock_guard<std::mutex> lock(mutex);
        if (!failure) failure = std::current_exception();
        session.halt();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      --running;
      finished.notify_all();
    });
  {
    std::unique_lock<std::mutex> lock(mutex);
    while (running > 0) {
      finished.wait_for(lock, std::chrono::milliseconds(50));
      if (cancel && cancel->load()) session.halt();
    }
  }
  for (auto& t : pool) t.join();
  if (failure) std::rethrow_exception(failure);
}

}  // namespace frictionlab::dynamics::ensemble
