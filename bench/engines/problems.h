#pragma once
// The four classical problems of the engines' side by side (docs/engines.md §6), each built from a
// shipped scenario so that the engines and frictionlab run the same body, k and start (one source
// of truth: data/scenarios/), with the quantity measured and its known answer:
//
//   spin-down      sphere-spinning.toml: a sphere spinning about the vertical in place. Measured: the
//                  time its spin falls to 1 % of the start. Answer: 0.99 T, T = 32 omega0 R^2/(15 pi k
//                  g a) (the spin moment (3 pi/16) k N a of a Hertz patch of radius a, N = m g, on a
//                  solid sphere C = 2/5 m R^2: C omega' = -(3 pi/16) k m g a; docs/engines.md §6).
//   puck           puck-disk.toml: a uniform disk sliding at 1 m/s and spinning at 20 1/s. Measured:
//                  v/(a omega) where the kinetic energy has fallen to 1e-3 of its start. Answer: the
//                  terminal ratio r* of the uniform disk under the exact law, a zero of the drift G(r)
//                  (dynamics/puck/terminal_ratio.h; 0.653, Farkas, Bartels, Unger & Wolf, PRL 90
//                  (2003) 248302), computed here, not typed in.
//   tippe-top      tippe-top.toml (Leine & Glocker 2003). Measured: the time the axis is inverted
//                  (gamma3 < -0.9, dynamics/tippe_top/tippe_top_observables.h). Answer: frictionlab's
//                  run with the exact law (no closed form exists).
//   slide-to-roll  sphere-sliding.toml: a sphere launched at v0 without spin. Measured: v/v0 at the
//                  end. Answer: 5/7, reached at t = 2 v0/(7 k g) (Coulomb friction k m g on the
//                  slip until v = omega R; e.g. Routh, Elementary Rigid Dynamics, 1905, §243).

#include <filesystem>
#include <string>
#include <vector>

#include "bench/engines/engine.h"

namespace frictionlab::engines {

struct Problem {
  std::string id;        ///< "spin-down", "puck", "tippe-top", "slide-to-roll"
  std::string title;     ///< for tables
  std::filesystem::path scenario;  ///< the shipped scenario it is built from
  std::string law;       ///< the scenario's law (`exact` or `exact:pressure=uniform`): frictionlab's row
  RunSpec spec;          ///< the body, start, k, g and duration for the engines (their own numerics: 0)
  double patch_radius = 0.0;  ///< m: frictionlab's static patch radius a (the engines' calibration)
  double spin_c = 0.0;   ///< the pure-spin moment per kNa of that patch (3 pi/16 Hertz, 2/3 uniform)
  std::string quantity;  ///< what is measured, with its unit
  /// The known answer of `quantity` (see the header comment); NaN for the tippe top until
  /// frictionlab's exact run gives it (bench/engines/frictionlab_runs.h).
  double answer = 0.0;
  std::string answer_source;  ///< where the answer comes from, one line
};

/// The spin-down closed form: the time a solid sphere of radius R spinning at omega0 about the
/// vertical on a Hertz patch of radius a takes to stop, 32 omega0 R^2/(15 pi k g a) (s).
[[nodiscard]] double spin_down_time(double omega0, double R, double k, double g, double a);
/// The time a solid sphere launched at v0 without spin slides before it rolls: 2 v0/(7 k g) (s).
[[nodiscard]] double slide_to_roll_time(double v0, double k, double g);

/// The four problems from the scenarios in `scenarios` (data/scenarios), in the order above.
/// std::invalid_argument if a scenario is missing or is not of the expected kind.
[[nodiscard]] std::vector<Problem> make_problems(const std::filesystem::path& scenarios);

}  // namespace frictionlab::engines
