#include "bench/accuracy/grid.h"

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <utility>

#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::accuracy {
namespace {

std::size_t nearest(const std::vector<double>& nodes, double value) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < nodes.size(); ++i) {
    if (std::abs(nodes[i] - value) < std::abs(nodes[best] - value)) best = i;
  }
  return best;
}

}  // namespace

bool GridSpec::is_valid(std::string* error) const {
  const auto count = [](std::size_t n) { return static_cast<long long>(n); };
  std::string msg;
  if (s_points < 2) {
    msg = support::invalid_value("s points", count(s_points), "the slip-ratio grid needs at least 2 points").what();
  } else if (mu_points < 2) {
    msg = support::invalid_value("mu points", count(mu_points),
                                 "the axis-ratio grid needs at least 2 points (mu_min and 1)")
              .what();
  } else if (psi_points < 3 || psi_points % 2 == 0) {
    msg = support::invalid_value("psi points", count(psi_points),
                                 "the orientation grid needs an odd number >= 3 of points, so that 0, pi/2 and pi "
                                 "are nodes")
              .what();
  } else if (!(std::isfinite(s_min) && s_min > 0.0)) {
    msg = support::invalid_value("s_min", s_min, "the smallest slip ratio must be finite and > 0").what();
  } else if (!(std::isfinite(s_max) && s_max > s_min)) {
    msg = support::invalid_value("s_max", s_max,
                                 "the largest slip ratio must be finite and > s_min = " + support::message_number(s_min))
              .what();
  } else if (!(mu_min > 0.0 && mu_min < 1.0)) {
    msg = support::invalid_value("mu_min", mu_min, "the smallest axis ratio must lie in (0, 1)").what();
  } else {
    return true;
  }
  if (error) *error = std::move(msg);
  return false;
}

friction::ContactInput to_contact(const GridPoint& p) {
  friction::ContactInput in;
  in.U = p.s;
  in.Omega = static_cast<double>(p.sign);
  in.a = 1.0;
  in.b = p.mu;
  in.psi = p.psi;
  in.N = 1.0;
  in.k = 1.0;
  return in;
}

Grid::Grid(const GridSpec& spec) : spec_(spec) {
  std::string error;
  if (!spec.is_valid(&error)) throw std::invalid_argument(error);

  const double l0 = std::log10(spec.s_min);
  const double l1 = std::log10(spec.s_max);
  s_.resize(spec.s_points);
  for (std::size_t i = 0; i < s_.size(); ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(s_.size() - 1);
    s_[i] = std::pow(10.0, l0 + t * (l1 - l0));
  }
  s_.front() = spec.s_min;  // exact ends, whatever pow rounds to
  s_.back() = spec.s_max;

  mu_.resize(spec.mu_points);
  for (std::size_t i = 0; i < mu_.size(); ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(mu_.size() - 1);
    mu_[i] = spec.mu_min + t * (1.0 - spec.mu_min);
  }
  mu_.front() = spec.mu_min;
  mu_.back() = 1.0;

  constexpr double pi = std::numbers::pi;
  psi_.resize(spec.psi_points);
  const std::size_t half = (psi_.size() - 1) / 2;
  for (std::size_t i = 0; i < psi_.size(); ++i) {
    psi_[i] = pi * static_cast<double>(i) / static_cast<double>(psi_.size() - 1);
  }
  psi_.front() = 0.0;
  psi_[half] = pi / 2.0;
  psi_.back() = pi;
}

GridPoint Grid::point(std::size_t i) const {
  GridPoint p;
  const std::size_t is = i % s_.size();
  i /= s_.size();
  const std::size_t isign = i % kSigns.size();
  i /= kSigns.size();
  const std::size_t ipsi = i % psi_.size();
  const std::size_t imu = i / psi_.size();
  p.s = s_[is];
  p.sign = kSigns[isign];
  p.psi = psi_[ipsi];
  p.mu = mu_[imu];
  return p;
}

std::size_t Grid::nearest_mu(double value) const { return nearest(mu_, value); }
std::size_t Grid::nearest_psi(double value) const { return nearest(psi_, value); }

}  // namespace frictionlab::accuracy
