#pragma once
// A puck scenario (docs/puck.md §2): a TOML file with `model = "puck"` and the sections [puck],
// [contact], [initial], [run], read through the same machinery as the body's scenarios
// (dynamics/body/scenario.h, dynamics/io/scenario_toml.h): unknown keys, wrong types and values out of
// range are std::invalid_argument naming the key and who set it (the file or a --set); resolved, it
// is the one source of truth of a run and its `resolved_toml` (scenario.toml beside the run)
// reproduces it.
//
//   model = "puck"
//   [puck]     mass (kg, required), a (m, required), b (m, default a), inertia (kg m^2, default
//              m (a^2 + b^2)/4, a uniform plate)
//   [contact]  k (required), g (m/s^2, default 9.81), law (default "exact"; any spec make_law takes)
//   [initial]  v = [vx, vy] (m/s, default 0), omega (1/s, default 0), heading (rad, default 0),
//              position = [x, y] (m, default 0)
//   [run]      as the body's (docs/dynamics.md §7) without the keys of a compliant contact
//              (settle_*, stop_when_rolling, max_stagnant_steps, rest_kinetic_energy) and of the
//              chatter event (max_chatter_steps, chatter_step: the puck holds a stopped slip or
//              spin at 0, so it cannot chatter, dynamics/puck/puck_run.h)

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/puck/puck.h"
#include "dynamics/puck/puck_state.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/simulation.h"

namespace frictionlab::dynamics::puck {

struct PuckInitial {
  Eigen::Vector2d position = Eigen::Vector2d::Zero();  ///< m
  double heading = 0.0;                                ///< rad, from x to the major axis
  Eigen::Vector2d v = Eigen::Vector2d::Zero();         ///< m/s
  double omega = 0.0;                                  ///< 1/s
};

struct PuckScenario {
  std::string name;
  std::string description;
  std::string source;
  std::vector<std::string> overrides;
  Puck puck;
  bool inertia_given = false;  ///< false: the uniform plate's default
  double k = 0.0;
  double g = 9.81;
  std::string law;             ///< a law spec (friction/registry.h)
  PuckInitial initial;
  RunOptions run;
  std::string resolved_toml;   ///< what scenario.toml beside a run contains
};

/// Limits of puck values beyond those the body shares (dynamics/body/scenario_limits.h).
struct PuckLimits {
  /// kappa = I/(m a^2) within [1e-6, 1e6]: a curling stone on its running band has ~2.5, a ring
  /// on its rim 1, a uniform disk 0.5; far outside, the spin and the slip live on time scales
  /// ~1/kappa apart.
  static constexpr double kMinInertiaRatio = 1e-6;
  static constexpr double kMaxInertiaRatio = 1e6;
};

/// The puck scenario of `doc` with `overrides` applied (the document's model must be "puck").
[[nodiscard]] PuckScenario resolve_puck(const ScenarioDocument& doc, const std::vector<std::string>& overrides = {});
[[nodiscard]] PuckScenario load_puck_scenario(const std::filesystem::path& file,
                                              const std::vector<std::string>& overrides = {});
[[nodiscard]] PuckScenario parse_puck_scenario(std::string_view toml_text, const std::string& source,
                                               const std::vector<std::string>& overrides = {});

/// The state at t = 0 (zero accumulated work).
[[nodiscard]] PuckState initial_state(const PuckScenario& s);

}  // namespace frictionlab::dynamics::puck
