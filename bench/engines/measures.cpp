#include "bench/engines/measures.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "dynamics/tippe_top/tippe_top_observables.h"
#include "friction/support/number_format.h"

namespace frictionlab::engines {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double horizontal_speed(const Sample& s) { return std::hypot(s.v[0], s.v[1]); }

// The first time y(i) falls to `level` or below, interpolated linearly between samples; NaN if never.
template <class Y>
double first_time_at_or_below(const std::vector<Sample>& samples, Y y, double level) {
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const double yi = y(samples[i]);
    if (yi <= level) {
      if (i == 0) return samples[0].t;
      const double y0 = y(samples[i - 1]);
      const double w = (y0 - level) / (y0 - yi);
      return samples[i - 1].t + w * (samples[i].t - samples[i - 1].t);
    }
  }
  return kNaN;
}

std::string s4(double x) { return std::isnan(x) ? "never" : support::significant(x, 4) + " s"; }

Measure spin_down(const std::vector<Sample>& samples) {
  const double w0 = std::abs(samples.front().omega[2]);
  const auto spin = [](const Sample& s) { return std::abs(s.omega[2]); };
  Measure m;
  m.value = first_time_at_or_below(samples, spin, 0.01 * w0);
  m.time = first_time_at_or_below(samples, spin, 1e-3 * w0);
  m.detail = "spin below 1e-3 of its start: " + s4(m.time);
  return m;
}

Measure puck(const Problem& p, const std::vector<Sample>& samples) {
  const double mass = p.spec.body.mass, C = p.spec.body.inertia[2], a = p.patch_radius;
  const auto energy = [&](const Sample& s) {
    const double v = horizontal_speed(s);
    return 0.5 * mass * v * v + 0.5 * C * s.omega[2] * s.omega[2];
  };
  const double e0 = energy(samples.front());
  Measure m;
  m.value = kNaN;
  for (std::size_t i = 1; i < samples.size(); ++i) {
    const double e1 = energy(samples[i]);
    if (e1 <= 1e-3 * e0) {
      // Interpolate the ratio between the two samples at the energy level.
      const double ea = energy(samples[i - 1]);
      const double w = (ea - 1e-3 * e0) / (ea - e1);
      const auto ratio = [&](const Sample& s) { return horizontal_speed(s) / (a * std::abs(s.omega[2])); };
      m.value = ratio(samples[i - 1]) + w * (ratio(samples[i]) - ratio(samples[i - 1]));
      break;
    }
  }
  const double v0 = horizontal_speed(samples.front()), w0 = std::abs(samples.front().omega[2]);
  const double t_v = first_time_at_or_below(samples, horizontal_speed, 1e-3 * v0);
  const double t_w = first_time_at_or_below(samples, [](const Sample& s) { return std::abs(s.omega[2]); }, 1e-3 * w0);
  m.time = std::isnan(t_v) || std::isnan(t_w) ? kNaN : std::max(t_v, t_w);
  std::string order = "";
  if (!std::isnan(t_v) && !std::isnan(t_w)) {
    order = std::abs(t_v - t_w) <= 0.01 * std::max(t_v, t_w) ? " (together)" : (t_v < t_w ? " (slip first)" : " (spin first)");
  }
  m.detail = "v to 1e-3 of v0: " + s4(t_v) + "; ω to 1e-3 of ω0: " + s4(t_w) + order;
  return m;
}

Measure tippe_top(const std::vector<Sample>& samples) {
  dynamics::tippe_top::InversionWatch watch;
  for (const Sample& s : samples) watch.add(s.t, axis_vertical(s.orientation));
  Measure m;
  m.value = watch.inversion_time();
  m.time = watch.horizontal_time();
  m.detail = "axis horizontal at " + s4(m.time) + "; lowest γ3 " + support::significant(watch.min_gamma3(), 3) +
             "; γ3 at the end " + support::significant(axis_vertical(samples.back().orientation), 3);
  return m;
}

Measure slide_to_roll(const Problem& p, const std::vector<Sample>& samples) {
  const double v0 = horizontal_speed(samples.front()), R = p.spec.body.radius;
  // The lowest point of the sphere is R below its centre; the centre moves with the centre of mass
  // (a sphere of these problems has its centre of mass at its centre).
  const auto slip = [R](const Sample& s) {
    const double ux = s.v[0] - s.omega[1] * R, uy = s.v[1] + s.omega[0] * R;  // v + omega x (-R e_z)
    return std::hypot(ux, uy);
  };
  Measure m;
  m.value = horizontal_speed(samples.back()) / v0;
  m.time = first_time_at_or_below(samples, slip, 0.01 * v0);
  m.detail = "slip below 1 % of v0 from " + s4(m.time);
  return m;
}

}  // namespace

double axis_vertical(const std::array<double, 4>& q) {
  const double n2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
  return 1.0 - 2.0 * (q[1] * q[1] + q[2] * q[2]) / n2;
}

Measure measure(const Problem& problem, const std::vector<Sample>& samples) {
  if (samples.empty()) throw std::invalid_argument("the run of '" + problem.id + "' has no samples");
  if (problem.id == "spin-down") return spin_down(samples);
  if (problem.id == "puck") return puck(problem, samples);
  if (problem.id == "tippe-top") return tippe_top(samples);
  if (problem.id == "slide-to-roll") return slide_to_roll(problem, samples);
  throw std::invalid_argument("problem '" + problem.id + "' is unknown");
}

}  // namespace frictionlab::engines
