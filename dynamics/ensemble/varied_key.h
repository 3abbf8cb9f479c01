#pragma once
// How the value of a varied key enters a run's scenario. A study varies scalars; the scenario
// holds some of them as vectors. So besides any scalar key of the scenario (`contact.k`,
// `initial.eps`, `body.mass`: passed on as the override key=value), a study may vary:
//
//   initial.gamma3            the tilt of the axis: gamma = (sqrt(1 - gamma3^2), 0, gamma3), the
//                             convention of the paper's cases (gamma2 = 0; docs/model.md §6);
//                             -1 <= gamma3 <= 1;
//   initial.omega1, omega2, omega3   one component of the angular velocity (1/s, body frame), the
//                             others as in the base scenario;
//   initial.v1, v2, v3        one component of the velocity of the centre of mass (m/s), likewise.
//
// The vectors a start changes are written out whole as overrides (initial.gamma = [...], with
// round-trip numbers), so the run's resolved scenario says exactly what ran.

#include <string>
#include <vector>

#include "dynamics/body/scenario.h"

namespace frictionlab::dynamics::ensemble {

class VariedKey {
 public:
  enum class Kind { plain, gamma3, omega, velocity };

  /// The key as a study writes it. A vector key of the scenario (initial.gamma, initial.omega,
  /// initial.v) is std::invalid_argument naming `where` and the scalar keys that vary it. For the
  /// puck (`puck`), initial.omega is its spin, a plain scalar key.
  static VariedKey parse(const std::string& key, const std::string& where, bool puck = false);

  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] Kind kind() const { return kind_; }
  [[nodiscard]] int component() const { return component_; }  ///< 0, 1, 2 for omega and velocity

 private:
  std::string name_;
  Kind kind_ = Kind::plain;
  int component_ = 0;
};

/// The initial vectors of a start and its plain overrides.
struct StartState {
  InitialState initial;                 ///< the base scenario's, with the derived keys applied
  bool gamma_set = false;               ///< a derived key or a replica changed gamma
  bool omega_set = false;               ///< ... omega
  bool velocity_set = false;            ///< ... v
  std::vector<std::string> overrides;   ///< plain keys: "key=value"
};

/// The start with `values[i]` for `keys[i]`, from the base scenario's initial state. An
/// out-of-range derived value (|gamma3| > 1, a non-finite value) is std::invalid_argument naming
/// the key and the rule.
[[nodiscard]] StartState apply_start(const InitialState& base, const std::vector<VariedKey>& keys,
                                     const std::vector<double>& values);

/// The overrides that make `state` part of a scenario: its plain overrides, then the vectors it
/// changed, written whole with round-trip numbers ("initial.gamma=[x, y, z]").
[[nodiscard]] std::vector<std::string> start_overrides(const StartState& state);

/// The overrides of a start of a puck scenario (`model = "puck"`, dynamics/puck/puck_scenario.h):
/// plain keys as key=value (the spin is the scalar initial.omega, the patch puck.b, ...); initial.v1
/// and initial.v2 set one component of the puck's velocity [vx, vy] (the other as in `base_v`),
/// written whole as initial.v=[vx, vy]. The body's derived keys (initial.gamma3, initial.omega1..3,
/// initial.v3) are std::invalid_argument naming the key: the puck has no tilt and one spin.
[[nodiscard]] std::vector<std::string> puck_start_overrides(const Eigen::Vector2d& base_v,
                                                            const std::vector<VariedKey>& keys,
                                                            const std::vector<double>& values);

}  // namespace frictionlab::dynamics::ensemble
