#include "bench/calibration/calibration.h"

#include <boost/math/tools/minima.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>
#include <stdexcept>

#include "friction/pressure.h"
#include "friction/registry.h"
#include "friction/support/errors.h"

namespace frictionlab::calibration {
namespace {

// Brent's method stops when c is known to about 2^-kBrentBits relative: 1.5e-8, far below the
// digits the tables print (4), and near the best a minimiser of a function of doubles can reach
// (about the square root of the double epsilon).
constexpr int kBrentBits = 26;

std::vector<std::size_t> scope_indices(const accuracy::Grid& grid, Scope scope) {
  std::vector<std::size_t> out;
  if (scope == Scope::circle) {
    const std::size_t imu = grid.mu().size() - 1;  // mu = 1 is the last node (grid.h)
    out.reserve(grid.slice_size());
    for (std::size_t i = imu * grid.slice_size(); i < (imu + 1) * grid.slice_size(); ++i) out.push_back(i);
  } else {
    out.resize(grid.size());
    for (std::size_t i = 0; i < grid.size(); ++i) out[i] = i;
  }
  return out;
}

// One engine law's values at the points of a scope (the other entries are left NaN).
accuracy::LawValues values_at(const friction::FrictionLaw& law, const accuracy::Grid& grid,
                              const std::vector<std::size_t>& indices) {
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  accuracy::LawValues v{std::string(law.spec()), std::vector<double>(grid.size(), nan),
                        std::vector<double>(grid.size(), nan), std::vector<double>(grid.size(), nan)};
  for (const std::size_t i : indices) {
    const auto f = law.evaluate(accuracy::to_contact(grid.point(i)));
    v.F1[i] = f.F1;
    v.F2[i] = f.F2;
    v.M[i] = f.M;
  }
  return v;
}

// E(c): the largest torque error of `law` with coefficient c over `indices`.
double max_torque_error(const EngineLaw& law, double c, const accuracy::Grid& grid,
                        const accuracy::LawValues& exact, const std::vector<std::size_t>& indices) {
  const auto made = make_engine_law(law, c, 1.0, 1.0);  // grid units: a = 1 m, k = 1
  double e = 0.0;
  for (const std::size_t i : indices) {
    const double M = made->evaluate(accuracy::to_contact(grid.point(i))).M;
    e = std::max(e, std::abs(M - exact.M[i]));
  }
  return e;
}

}  // namespace

std::vector<std::string> exact_pressures() {
  for (const auto& parameter : friction::law_info(friction::reference_law_name()).parameters) {
    if (parameter.key == "pressure") return parameter.choices;
  }
  return {friction::pressure_names().front()};  // a reference law without the parameter: its default
}

double circle_spin_closed_form(const std::string& name) {
  return std::numbers::pi / 2.0 * friction::pressure_pure_spin_factor(friction::parse_pressure(name));
}

std::string exact_spec(const std::string& pressure) {
  return friction::reference_law_name() + ":pressure=" + pressure;
}

const char* scope_name(Scope scope) { return scope == Scope::circle ? "circle" : "grid"; }

bool CalibrationOptions::is_valid(std::string* error) const {
  const auto fail = [error](std::string message) {
    if (error) *error = std::move(message);
    return false;
  };
  std::string grid_error;
  if (!grid.is_valid(&grid_error)) return fail(grid_error);
  if (!(std::isfinite(c_min) && c_min > 0.0)) {
    return fail(support::invalid_value("c_min", c_min, "must be a finite number > 0").what());
  }
  if (!(std::isfinite(c_max) && c_max > c_min)) {
    return fail(support::invalid_value("c_max", c_max, "must be a finite number > c_min").what());
  }
  if (scan_points < 3) {
    return fail(support::invalid_value("scan_points", static_cast<long long>(scan_points), "must be >= 3").what());
  }
  try {
    for (const auto& l : laws) (void)engine_law(l);
    const auto known = exact_pressures();
    for (const auto& p : pressures) {
      if (std::find(known.begin(), known.end(), p) == known.end()) {
        std::string list;
        for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
        return fail("pressure model '" + p + "' is not one the exact law offers: " + list);
      }
    }
  } catch (const std::invalid_argument& e) {
    return fail(e.what());
  }
  return true;
}

Errors errors_over(const accuracy::LawValues& law, const accuracy::LawValues& exact,
                   const std::vector<std::size_t>& indices, double c) {
  Errors e;
  e.c = c;
  const std::array<const std::vector<double>*, 3> lv = {&law.F1, &law.F2, &law.M};
  const std::array<const std::vector<double>*, 3> ev = {&exact.F1, &exact.F2, &exact.M};
  std::array<double, 3> sum2{};
  for (const std::size_t i : indices) {
    for (std::size_t k = 0; k < 3; ++k) {
      const double d = std::abs((*lv[k])[i] - (*ev[k])[i]);
      if (k == 2 && d > e.max[2]) e.worst_M = i;
      e.max[k] = std::max(e.max[k], d);
      sum2[k] += d * d;
    }
  }
  for (std::size_t k = 0; k < 3; ++k) {
    e.rms[k] = indices.empty() ? 0.0 : std::sqrt(sum2[k] / static_cast<double>(indices.size()));
  }
  return e;
}

CalibrationResult run_calibration(const CalibrationOptions& options) {
  std::string error;
  if (!options.is_valid(&error)) throw std::invalid_argument(error);
  const auto t0 = std::chrono::steady_clock::now();
  CalibrationResult result{accuracy::Grid(options.grid), {}, {}, {}, 0.0};
  const accuracy::Grid& grid = result.grid;

  std::vector<const EngineLaw*> laws;
  for (const auto& l : engine_laws()) {
    if (options.laws.empty() || std::find(options.laws.begin(), options.laws.end(), l.name) != options.laws.end())
      laws.push_back(&l);
  }
  std::vector<std::string> chosen;
  for (const auto& p : exact_pressures()) {
    if (options.pressures.empty() || std::find(options.pressures.begin(), options.pressures.end(), p) != options.pressures.end())
      chosen.push_back(p);
  }

  // The scan of c, log-spaced, both ends exact.
  std::vector<double> scan(options.scan_points);
  for (std::size_t j = 0; j < scan.size(); ++j) {
    const double t = static_cast<double>(j) / static_cast<double>(scan.size() - 1);
    scan[j] = j + 1 == scan.size() ? options.c_max : options.c_min * std::pow(options.c_max / options.c_min, t);
  }

  const std::array<Scope, 2> scopes = {Scope::circle, Scope::grid};
  std::array<std::vector<std::size_t>, 2> indices = {scope_indices(grid, Scope::circle),
                                                     scope_indices(grid, Scope::grid)};
  // The circle's curves: psi = 0 (any psi gives the same on a circle), Omega > 0.
  std::vector<std::size_t> curve_points;
  for (std::size_t is = 0; is < grid.s().size(); ++is) curve_points.push_back(grid.index(grid.mu().size() - 1, 0, 1, is));
  const auto curve_of = [&](const std::string& p, const std::string& label, const accuracy::LawValues& v) {
    Curve c{p, label, {}, {}};
    for (const std::size_t i : curve_points) {
      c.F1.push_back(v.F1[i]);
      c.M.push_back(v.M[i]);
    }
    return c;
  };

  for (const std::string& p : chosen) {
    const auto exact = friction::make_law(exact_spec(p));
    const auto te = std::chrono::steady_clock::now();
    const accuracy::LawValues ref = accuracy::evaluate_on_grid(*exact, grid, options.threads);
    if (options.progress) {
      *options.progress << "calibrate: " << exact->spec() << " on " << grid.size() << " points in "
                        << std::chrono::duration<double>(std::chrono::steady_clock::now() - te).count() << " s"
                        << std::endl;
    }
    const double spin = exact->evaluate({0.0, 1.0, 1.0, 1.0, 0.0, 1.0, 1.0}).M;
    result.curves.push_back(curve_of(p, std::string(exact->spec()), ref));

    for (const EngineLaw* law : laws) {
      for (std::size_t sc = 0; sc < scopes.size(); ++sc) {
        const auto& idx = indices[sc];
        CalibrationRow row;
        row.law = law->name;
        row.pressure = p;
        row.scope = scopes[sc];
        row.exact_circle_spin = spin;
        const auto E = [&](double c) {
          ++row.objective_evaluations;
          return max_torque_error(*law, c, grid, ref, idx);
        };
        ScanCurve curve{law->name, p, scopes[sc], scan, {}};
        for (const double c : scan) curve.max_error_M.push_back(E(c));
        // E is unimodal (header): the scan's smallest value and its neighbours bracket the minimum.
        const auto jmin = static_cast<std::size_t>(
            std::min_element(curve.max_error_M.begin(), curve.max_error_M.end()) - curve.max_error_M.begin());
        const double lo = scan[jmin == 0 ? 0 : jmin - 1];
        const double hi = scan[std::min(jmin + 1, scan.size() - 1)];
        auto [c_best, e_best] = boost::math::tools::brent_find_minima(E, lo, hi, kBrentBits);
        if (curve.max_error_M[jmin] < e_best) c_best = scan[jmin];  // never worse than the scan

        const auto at = [&](double c) {
          const auto made = make_engine_law(*law, c, 1.0, 1.0);
          return errors_over(values_at(*made, grid, idx), ref, idx, c);
        };
        row.at_spin = at(spin);
        row.best = at(c_best);
        result.rows.push_back(row);
        result.scans.push_back(std::move(curve));
        if (scopes[sc] == Scope::circle) {
          const auto made = make_engine_law(*law, c_best, 1.0, 1.0);
          result.curves.push_back(curve_of(p, std::string(made->spec()), values_at(*made, grid, curve_points)));
        }
      }
      if (options.progress) *options.progress << "calibrate: " << law->name << " against " << exact->spec() << std::endl;
    }
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace frictionlab::calibration
