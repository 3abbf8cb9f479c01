#pragma once
// A law evaluated at every point of the accuracy grid, in parallel over the mu slices.

#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/accuracy/grid.h"
#include "friction/law.h"

namespace frictionlab::accuracy {

/// F1/(kN), F2/(kN), M/(kNa) of one law at every grid point, indexed like Grid::index.
struct LawValues {
  std::string law;
  std::vector<double> F1, F2, M;
};

/// Evaluates `law` at every point of `grid` with `threads` worker threads (0: one per hardware
/// thread), each taking whole mu slices. An exception thrown by the law is rethrown (as
/// std::runtime_error) naming the law and the point. The law must be safe to call concurrently,
/// which friction::FrictionLaw promises.
[[nodiscard]] LawValues evaluate_on_grid(const friction::FrictionLaw& law, const Grid& grid,
                                         std::size_t threads = 0);

/// The number of worker threads `threads` stands for (0: hardware concurrency, at least 1),
/// never more than `work_items`.
[[nodiscard]] std::size_t worker_count(std::size_t threads, std::size_t work_items);

}  // namespace frictionlab::accuracy
