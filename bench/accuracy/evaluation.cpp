#include "bench/accuracy/evaluation.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <span>
#include <stdexcept>
#include <string>
#include <thread>

#include "friction/support/number_format.h"

namespace frictionlab::accuracy {

std::size_t worker_count(std::size_t threads, std::size_t work_items) {
  std::size_t n = threads != 0 ? threads : std::max(1u, std::thread::hardware_concurrency());
  return std::max<std::size_t>(1, std::min(n, work_items));
}

LawValues evaluate_on_grid(const friction::FrictionLaw& law, const Grid& grid, std::size_t threads) {
  LawValues out;
  out.law = std::string(law.spec());  // the spec verbatim (friction/law_spec.h)
  out.F1.resize(grid.size());
  out.F2.resize(grid.size());
  out.M.resize(grid.size());

  std::atomic<std::size_t> next_slice{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  // A slice (one axis ratio) at a time, evaluated in one call (the law's batch evaluation).
  auto work = [&] {
    std::vector<friction::ContactInput> in(grid.slice_size());
    std::vector<friction::FrictionForces> f(grid.slice_size());
    for (std::size_t imu = next_slice++; imu < grid.mu().size(); imu = next_slice++) {
      const std::size_t begin = imu * grid.slice_size();
      for (std::size_t j = 0; j < in.size(); ++j) in[j] = to_contact(grid.point(begin + j));
      try {
        law.evaluate(std::span<const friction::ContactInput>(in), std::span<friction::FrictionForces>(f));
      } catch (const friction::BatchError& e) {
        const GridPoint p = grid.point(begin + e.index());
        const std::string msg = "law '" + std::string(law.name()) + "' failed at s = " + support::message_number(p.s) +
                                ", mu = " + support::message_number(p.mu) + ", psi = " + support::message_number(p.psi) +
                                ", sign(Omega) = " + std::to_string(p.sign) + ": " + e.cause_message();
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::make_exception_ptr(std::runtime_error(msg));
        next_slice = grid.mu().size();  // stop the other workers early
        return;
      }
      for (std::size_t j = 0; j < f.size(); ++j) {
        out.F1[begin + j] = f[j].F1;
        out.F2[begin + j] = f[j].F2;
        out.M[begin + j] = f[j].M;
      }
    }
  };

  const std::size_t n = worker_count(threads, grid.mu().size());
  std::vector<std::thread> pool;
  pool.reserve(n - 1);
  for (std::size_t t = 1; t < n; ++t) pool.emplace_back(work);
  work();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);
  return out;
}

}  // namespace frictionlab::accuracy
