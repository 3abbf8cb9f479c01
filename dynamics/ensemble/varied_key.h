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
//   initial.v1, v2, v3        one component of the velocity of the centre of mass (m/s), likewise;
//   body.misalignment         delta (rad): the base body's central inertia tensor J with its
//                             horizontal principal axes turned by delta about e3 (counter-clockwise
//                             seen from above, right-hand rule) from e1, e2, keeping its principal
//                             moments (docs/ensembles.md §1). Precisely: e3 must be a principal axis
//                             of J (J13 = J23 = 0); of J's two horizontal principal moments, A is the
//                             one whose axis is nearest e1 (the axis at |angle| < pi/4 from e1), B
//                             the other, C = J33; the key's value is the tensor
//                             shapes::inertia_from_principal((A, B, C), e3, delta), so delta = 0 is
//                             diag(A, B, C) and the base itself is delta = its own angle. A rattleback
//                             (A < B: the long axis e1 has the smaller moment) then has
//                             delta = rigid_rolling::misalignment_angle(J); the Kane & Levinson one
//                             (J12 = +0.2e-4 kg m^2) has delta = -0.0143 rad. Rules: |delta| < pi/4
//                             (the axis of A stays the one nearest e1, so that delta names one
//                             tensor); J11 != J22 (equal horizontal moments have no misalignment to
//                             turn; with J12 != 0 their axes are at 45 degrees to e1 and "nearest e1"
//                             names none). Not a key of the puck.
//
// The vectors a start changes are written out whole as overrides (initial.gamma = [...], with
// round-trip numbers), and so is a changed tensor (body.inertia = [[...], [...], [...]]), so the
// run's resolved scenario says exactly what ran.

#include <string>
#include <vector>

#include "dynamics/body/scenario.h"

namespace frictionlab::dynamics::ensemble {

class VariedKey {
 public:
  enum class Kind { plain, gamma3, omega, velocity, misalignment };

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

/// The initial vectors of a start, its body's inertia tensor and its plain overrides.
struct StartState {
  InitialState initial;                 ///< the base scenario's, with the derived keys applied
  Eigen::Matrix3d inertia = Eigen::Matrix3d::Identity();  ///< the base body's J (kg m^2), likewise
  bool gamma_set = false;               ///< a derived key or a replica changed gamma
  bool omega_set = false;               ///< ... omega
  bool velocity_set = false;            ///< ... v
  bool inertia_set = false;             ///< body.misalignment changed the inertia tensor
  std::vector<std::string> overrides;   ///< plain keys: "key=value"
};

/// The start with `values[i]` for `keys[i]`, from the base scenario's initial state and its body's
/// central inertia tensor `base_inertia` (Body::inertia, kg m^2). An out-of-range derived value
/// (|gamma3| > 1, |misalignment| >= pi/4, a non-finite value) or a base tensor body.misalignment
/// cannot turn is std::invalid_argument naming the key and the rule.
[[nodiscard]] StartState apply_start(const InitialState& base, const Eigen::Matrix3d& base_inertia,
                                     const std::vector<VariedKey>& keys, const std::vector<double>& values);

/// The overrides that make `state` part of a scenario: its plain overrides, then the tensor and the
/// vectors it changed, written whole with round-trip numbers ("body.inertia=[[a, b, c], [d, e, f],
/// [g, h, i]]", "initial.gamma=[x, y, z]").
[[nodiscard]] std::vector<std::string> start_overrides(const StartState& state);

/// The overrides of a start of a puck scenario (`model = "puck"`, dynamics/puck/puck_scenario.h):
/// plain keys as key=value (the spin is the scalar initial.omega, the patch puck.b, ...); initial.v1
/// and initial.v2 set one component of the puck's velocity [vx, vy] (the other as in `base_v`),
/// written whole as initial.v=[vx, vy]. The body's derived keys (initial.gamma3, initial.omega1..3,
/// initial.v3, body.misalignment) are std::invalid_argument naming the key: the puck has no tilt,
/// one spin and no inertia tensor.
[[nodiscard]] std::vector<std::string> puck_start_overrides(const Eigen::Vector2d& base_v,
                                                            const std::vector<VariedKey>& keys,
                                                            const std::vector<double>& values);

}  // namespace frictionlab::dynamics::ensemble
