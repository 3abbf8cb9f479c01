#include "bench/accuracy/evaluation.h"

#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <thread>

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
  auto work = [&] {
    for (std::size_t imu = next_slice++; imu < grid.mu().size(); imu = next_slice++) {
      const std::size_t begin = imu * grid.slice_size();
      const std::size_t end = begin + grid.slice_size();
      for (std::size_t i = begin; i < end; ++i) {
        const GridPoint p = grid.point(i);
        try {
          const auto f = law.evaluate(to_contact(p));
          out.F1[i] = f.F1;
          out.F2[i] = f.F2;
          out.M[i] = f.M;
        } catch (const std::exception& e) {
          std::ostringstream msg;
          msg.precision(10);
          msg << "law '" << law.name() << "' failed at s = " << p.s << ", mu = " << p.mu
              << ", psi = " << p.psi << ", sign(Omega) = " << p.sign << ": " << e.what();
          const std::lock_guard lock(error_mutex);
          if (!error) error = std::make_exception_ptr(std::runtime_error(msg.str()));
          next_slice = grid.mu().size();  // stop the other workers early
          return;
        }
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
