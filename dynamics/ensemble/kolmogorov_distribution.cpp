#include "dynamics/ensemble/kolmogorov_distribution.h"

#include <cmath>
#include <numbers>

namespace frictionlab::dynamics::ensemble {
namespace {

constexpr double kTermTolerance = 1e-17;
constexpr int kMaxTerms = 100;  // z >= 0.05 (or <= 1.18 on the other side) needs < 10

}  // namespace

// 2 sum (-1)^(j-1) exp(-2 j^2 z^2), NR3 eq. (6.14.56).
double kolmogorov_q_series(double z) {
  double sum = 0.0;
  for (int j = 1; j <= kMaxTerms; ++j) {
    const double term = std::exp(-2.0 * j * j * z * z);
    sum += (j % 2 == 1 ? term : -term);
    if (term <= kTermTolerance * sum) break;
  }
  return 2.0 * sum;
}

// sqrt(2 pi)/z sum exp(-(2j-1)^2 pi^2 / (8 z^2)), NR3 eq. (6.14.57).
double kolmogorov_p_series(double z) {
  const double a = std::numbers::pi * std::numbers::pi / (8.0 * z * z);
  double sum = 0.0;
  for (int j = 1; j <= kMaxTerms; ++j) {
    const double k = 2.0 * j - 1.0;
    const double term = std::exp(-k * k * a);
    sum += term;
    if (term <= kTermTolerance * sum) break;
  }
  return std::sqrt(2.0 * std::numbers::pi) / z * sum;
}

double kolmogorov_q(double z) {
  if (!(z > 0.0)) return 1.0;
  return z < kKolmogorovSwitch ? 1.0 - kolmogorov_p_series(z) : kolmogorov_q_series(z);
}

double kolmogorov_p(double z) {
  if (!(z > 0.0)) return 0.0;
  return z < kKolmogorovSwitch ? kolmogorov_p_series(z) : 1.0 - kolmogorov_q_series(z);
}

}  // namespace frictionlab::dynamics::ensemble
