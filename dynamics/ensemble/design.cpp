#include "dynamics/ensemble/design.h"

#include <gsl/gsl_qrng.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "dynamics/ensemble/random_stream.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::ensemble {

std::string_view to_string(DesignKind kind) {
  switch (kind) {
    case DesignKind::grid: return "grid";
    case DesignKind::random: return "random";
    case DesignKind::sobol: return "sobol";
    case DesignKind::lhs: return "lhs";
  }
  return "unknown";
}

std::vector<UnitPoint> grid_product(const std::vector<std::vector<double>>& axes) {
  std::vector<UnitPoint> points{UnitPoint{}};
  for (const auto& axis : axes) {
    std::vector<UnitPoint> next;
    next.reserve(points.size() * axis.size());
    for (const auto& p : points)
      for (const double v : axis) {
        UnitPoint q = p;
        q.push_back(v);
        next.push_back(std::move(q));
      }
    points = std::move(next);
  }
  return points;
}

std::vector<UnitPoint> random_points(int dims, long n, std::uint64_t seed) {
  RandomStream rng(seed);
  std::vector<UnitPoint> points(static_cast<std::size_t>(n), UnitPoint(static_cast<std::size_t>(dims)));
  for (auto& p : points)
    for (auto& x : p) x = rng.uniform();
  return points;
}

std::vector<UnitPoint> sobol_points(int dims, long n) {
  if (dims < 1 || dims > kSobolMaxDimension)
    throw support::invalid_value("the number of dimensions of a Sobol design", static_cast<long long>(dims),
                                 "GSL's Sobol sequence has 1 to " + std::to_string(kSobolMaxDimension));
  struct Free {
    void operator()(gsl_qrng* q) const { gsl_qrng_free(q); }
  };
  const std::unique_ptr<gsl_qrng, Free> q(gsl_qrng_alloc(gsl_qrng_sobol, static_cast<unsigned>(dims)));
  if (!q) throw std::runtime_error("GSL could not allocate a Sobol generator");
  std::vector<UnitPoint> points(static_cast<std::size_t>(n), UnitPoint(static_cast<std::size_t>(dims)));
  for (auto& p : points) gsl_qrng_get(q.get(), p.data());
  return points;
}

std::vector<UnitPoint> latin_hypercube(int dims, long n, std::uint64_t seed) {
  RandomStream rng(seed);
  std::vector<UnitPoint> points(static_cast<std::size_t>(n), UnitPoint(static_cast<std::size_t>(dims)));
  for (int d = 0; d < dims; ++d) {
    const std::vector<long> strata = rng.permutation(n);
    for (long i = 0; i < n; ++i) {
      const double offset = rng.uniform();
      points[static_cast<std::size_t>(i)][static_cast<std::size_t>(d)] =
          (static_cast<double>(strata[static_cast<std::size_t>(i)]) + offset) / static_cast<double>(n);
    }
  }
  return points;
}

}  // namespace frictionlab::dynamics::ensemble
