#pragma once
// The calibration study: for each engine law (engine_laws.h) and each pressure model of the exact
// law, the coefficient c that matches `exact` at pure spin and the one that minimises the largest
// torque error over the grid of the accuracy study, with the errors each leaves (docs/engines.md).
//
// The grid is the accuracy study's (bench/accuracy/grid.h: a = 1 m, N = 1 N, k = 1, so F1, F2 are
// per kN and M per kNa, and c is the parameter in units of a, or of k a). Two scopes: the circle
// (mu = 1, the patch of a sphere on a plane: what docs/engines.md advises on) and the whole grid
// (mu in [mu_min, 1]).
//
// The objective is E(c) = max over the scope of |M_law(c) - M_exact| / (kNa): the spin torque is
// what the coefficient is for. The engine laws' M grows with c at every point (c^2/sqrt(c^2 + s^2)
// for the ellipsoidal and MuJoCo laws, c for the decoupled one), so each |M_law(c) - M_exact| is
// quasi-convex in c and so is their maximum: E has one minimum, which a scan brackets and Brent's
// method (boost::math::tools::brent_find_minima) refines. The errors of F1 and F2 at the chosen c
// are reported beside it (F2 = 0 for every engine law: its error is the same for every c).

#include <array>
#include <cstddef>
#include <iosfwd>
#include <string>
#include <vector>

#include "bench/accuracy/evaluation.h"
#include "bench/accuracy/grid.h"
#include "bench/calibration/engine_laws.h"

namespace frictionlab::calibration {

/// The pressure models the exact law declares (its `pressure` choices, friction/pressure.h), in
/// its order: the default set of the study.
[[nodiscard]] std::vector<std::string> exact_pressures();
/// The closed form of the exact pure-spin torque of a circle per kNa under pressure `name`:
/// (pi/2) pressure_pure_spin_factor, i.e. Hertz 3 pi/16, uniform 2/3, punch pi/4.
[[nodiscard]] double circle_spin_closed_form(const std::string& name);
/// The spec of the exact law with that pressure ("exact:pressure=uniform").
[[nodiscard]] std::string exact_spec(const std::string& pressure);

struct CalibrationOptions {
  accuracy::GridSpec grid;          ///< defaults: the accuracy study's grid
  std::vector<std::string> laws;    ///< engine laws; empty: all of engine_laws()
  std::vector<std::string> pressures;  ///< pressure models; empty: exact_pressures()
  double c_min = 0.05;              ///< the scan of E(c): c log-spaced over [c_min, c_max]
  double c_max = 2.0;
  std::size_t scan_points = 121;    ///< >= 3
  std::size_t threads = 0;          ///< for the exact law's values (0: one per hardware thread)
  std::ostream* progress = nullptr;  ///< one line per evaluated law, if given

  /// True if usable; otherwise false, with `error` naming the value and the rule.
  bool is_valid(std::string* error) const;
};

/// The errors one engine law leaves at one coefficient over one scope, per kN and kNa, with the
/// grid point where the torque error is largest.
struct Errors {
  double c = 0.0;
  std::array<double, 3> max{};  ///< largest |law - exact| of F1, F2, M
  std::array<double, 3> rms{};
  std::size_t worst_M = 0;      ///< grid index of the largest torque error
};

enum class Scope { circle, grid };
[[nodiscard]] const char* scope_name(Scope scope);  // "circle", "grid"

/// One row of the results: an engine law, a pressure model, a scope.
struct CalibrationRow {
  std::string law;
  std::string pressure;
  Scope scope = Scope::circle;
  double exact_circle_spin = 0.0;  ///< M/(kNa) of the exact law at U = 0 on the circle, computed
  Errors at_spin;                  ///< c = exact_circle_spin: exact at pure spin on the circle
  Errors best;                     ///< c minimising the largest torque error over the scope
  std::size_t objective_evaluations = 0;
};

/// E(c) on the scan, per (law, pressure, scope), for the figures.
struct ScanCurve {
  std::string law, pressure;
  Scope scope = Scope::circle;
  std::vector<double> c, max_error_M;
};

/// F1 and M against s on the circle (psi = 0, Omega > 0, mu = 1) for one pressure: the exact law's,
/// and each engine law's at its best c for the circle, for the figure of the forces.
struct Curve {
  std::string pressure;
  std::string label;       ///< the law's spec in grid units, e.g. "decoupled:r_spin=0.59"
  std::vector<double> F1;  ///< per kN, at the grid's s
  std::vector<double> M;   ///< per kNa
};

struct CalibrationResult {
  accuracy::Grid grid;
  std::vector<CalibrationRow> rows;  ///< per pressure, then law, then scope (circle, grid)
  std::vector<ScanCurve> scans;      ///< same order
  std::vector<Curve> curves;         ///< per pressure: exact, then each law at its best c (circle)
  double seconds = 0.0;
};

/// The largest |M_law - M_exact| over `indices`, and the other errors, for `law` (values at every
/// grid point) against `exact`.
[[nodiscard]] Errors errors_over(const accuracy::LawValues& law, const accuracy::LawValues& exact,
                                 const std::vector<std::size_t>& indices, double c);

/// Runs the study. std::invalid_argument on bad options (unknown law or pressure, bad grid).
[[nodiscard]] CalibrationResult run_calibration(const CalibrationOptions& options);

}  // namespace frictionlab::calibration
