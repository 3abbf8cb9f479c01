#pragma once
// The interface every friction law of frictionlab implements.
//
// Conventions (docs/model.md): the contact patch is an ellipse with semi-axes a >= b > 0 in the plane of contact, gamma the upward unit normal.
// e1 is the direction of the sliding velocity of the patch centre (speed U >= 0),
// e2 = gamma x e1, Omega = omega . gamma the signed spin, psi the angle from e1 to the major axis,
// counter-clockwise about gamma. The law returns F1, F2, M such that the friction force on the body
// is F = -F1 e1 - F2 e2 and the friction torque about the patch centre is -M gamma.

#include <cstddef>
#include <exception>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "friction/patch_angle.h"

namespace frictionlab::friction {

/// The state of one contact, as a friction law sees it. SI units.
struct ContactInput {
  double U = 0.0;      ///< slip speed of the patch centre, m/s; finite, >= 0
  double Omega = 0.0;  ///< spin about the upward normal, 1/s; finite, either sign
  double a = 1.0;      ///< major semi-axis of the patch, m; finite, > 0
  double b = 1.0;      ///< minor semi-axis of the patch, m; finite, 0 < b <= a
  PatchAngle psi;      ///< angle from e1 to the major axis, rad, CCW about gamma, with its cosine and
                       ///< sine (friction/patch_angle.h): an angle, finite, or a direction, unit
  double N = 0.0;      ///< normal force, N; finite, >= 0
  double k = 0.0;      ///< Coulomb friction coefficient, dimensionless; finite, >= 0
};

/// What a law returns: F = -F1 e1 - F2 e2 (N) on the body, torque -M gamma (N m).
struct FrictionForces {
  double F1 = 0.0;  ///< N, along -e1
  double F2 = 0.0;  ///< N, along -e2
  double M = 0.0;   ///< N m, about -gamma
};

/// The denominators of a rational law's outputs at one contact, divided by (a Omega)^2 (a positive
/// factor: only their signs matter). A law is singular (has a pole) where one of them changes sign
/// along a motion; NaN marks an output that has no denominator there. Regular laws have none.
struct PoleDenominators {
  double F1, F2, M;
};

/// Throws std::invalid_argument naming the offending value and the rule it breaks. Beyond the
/// per-field rules above, the scales every law needs must be doubles: the largest friction force
/// k N and the largest moment k N a must not overflow, and the axis ratio b/a must be at least the
/// smallest normal double (2.2e-308; a thinner patch is a line). k N may underflow: friction
/// below the smallest double is returned as 0.
void validate(const ContactInput& in);

/// U / (length |Omega|) for validated inputs (U >= 0, length > 0, Omega != 0, all finite), with
/// no spurious overflow or underflow of length |Omega|: at most two roundings whenever the result
/// is a normal double, +inf only if it is above the double range, 0 or subnormal only if below.
/// With length = a this is the slip ratio s on which every law depends.
[[nodiscard]] double slip_ratio(double U, double length, double Omega);

/// How an output behaves when the spin Omega changes sign (U, a, b, psi, N, k fixed).
enum class Parity { none, even, odd };

/// What a law guarantees at every valid input, to within `tolerance` (per kN for forces, per kNa
/// for the moment). The exact law has every property (docs/model.md lists them); an approximate
/// law declares those it keeps. tests/friction/law_soundness_test.cpp checks every promise of
/// every registered law. Whatever it promises, every law returns finite values for every valid
/// input or throws std::invalid_argument (input outside its own domain, e.g. on a pole), and
/// satisfies the limits N = 0 (no friction), Omega = 0 (F1 = kN, F2 = M = 0) and U = 0
/// (F1 = F2 = 0, M Omega > 0).
struct LawPromises {
  Parity F1_in_Omega = Parity::none;
  Parity F2_in_Omega = Parity::none;
  Parity M_in_Omega = Parity::none;
  bool pi_periodic_in_psi = false;  ///< psi -> psi + pi changes nothing (the patch's symmetry)
  bool psi_mirror = false;          ///< psi -> -psi flips the sign of F2 only
  bool dissipative = false;         ///< F1 U + M Omega >= 0: friction never adds energy
  bool bounded = false;             ///< F1^2 + F2^2 <= (kN)^2 and |M| <= kN a
  bool exact_pure_spin = false;     ///< U = 0: M = pure_spin_factor k N a E(e) sign(Omega),
                                    ///< e^2 = 1 - mu^2
  double pure_spin_factor = 3.0 / 8.0;  ///< of the law's pressure: 3/8 Hertz, 4/(3 pi) uniform,
                                        ///< 1/2 flat punch (docs/pressure-models.md)
  double min_axis_ratio = 0.0;      ///< b/a below this is rejected with std::invalid_argument
  bool whole_domain = false;        ///< evaluates every input validate() accepts with
                                    ///< b/a >= min_axis_ratio, never throwing
  double tolerance = 0.0;           ///< per kN and kNa, to which the promises hold

  /// What every closed-form law without F2 and without psi keeps (the ellipsoidal, MuJoCo and
  /// decoupled laws): F1 even and M odd in Omega, F2 = 0, psi plays no part, dissipative, to the
  /// rounding of a closed form (1e-14). The rest (bounded, whole_domain, pure spin) is the law's.
  [[nodiscard]] static LawPromises closed_form_without_F2();
};

/// Where an evaluation of many contacts (FrictionLaw::evaluate of spans) stopped, and why: the index
/// of the contact, and the exception evaluate() of that contact alone throws (cause(), to rethrow);
/// what() is "contact INDEX: " and the cause's message.
class BatchError : public std::invalid_argument {
 public:
  BatchError(std::size_t index, std::exception_ptr cause, const std::string& cause_message);
  [[nodiscard]] std::size_t index() const { return index_; }
  [[nodiscard]] std::exception_ptr cause() const { return cause_; }
  [[nodiscard]] const std::string& cause_message() const { return cause_message_; }

 private:
  std::size_t index_;
  std::exception_ptr cause_;
  std::string cause_message_;
};

/// A law of coupled dry friction. Implementations are `final`, stateless after construction,
/// and safe to call concurrently from several threads.
class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  /// Registry name, e.g. "exact", "pade-printed".
  [[nodiscard]] virtual std::string_view name() const = 0;
  /// One line: what the law is and where it comes from.
  [[nodiscard]] virtual std::string_view summary() const = 0;
  /// The spec this law was made from by make_law() (friction/registry.h), verbatim, e.g.
  /// "exact:pressure=uniform"; name() for a law constructed directly. Outputs name a law by it.
  [[nodiscard]] std::string_view spec() const { return spec_.empty() ? name() : std::string_view(spec_); }

  /// True if the law has denominators that can vanish at valid input (its singular set), which
  /// pole_denominators() then returns. Callers watch their signs (simulation events, accuracy
  /// study) instead of branching on the law's name.
  [[nodiscard]] virtual bool has_poles() const { return false; }
  /// The denominators at `in` (validated input with Omega != 0); all NaN for a law without poles.
  [[nodiscard]] virtual PoleDenominators pole_denominators(const ContactInput& in) const;
  /// The properties the law guarantees (see LawPromises); none by default.
  [[nodiscard]] virtual LawPromises promises() const { return {}; }

  /// Validates `in` (std::invalid_argument on bad input), then evaluates the law.
  [[nodiscard]] FrictionForces evaluate(const ContactInput& in) const {
    validate(in);
    return do_evaluate(in);
  }

  /// Evaluates every contact of `in` into the same position of `out`: the values evaluate() gives
  /// each, bit for bit, in one call (a law may evaluate several contacts at once, e.g. across SIMD
  /// lanes). `in` and `out` have the same size (std::invalid_argument otherwise). At the first
  /// contact that is invalid or that the law rejects it throws BatchError (its index, the cause);
  /// `out` then holds the results of the contacts before it.
  void evaluate(std::span<const ContactInput> in, std::span<FrictionForces> out) const;

 protected:
  FrictionLaw() = default;
  FrictionLaw(const FrictionLaw&) = default;
  FrictionLaw& operator=(const FrictionLaw&) = default;

 private:
  /// Sets spec(): the registry's, which knows the spec a law was made from (found by ADL).
  friend void set_law_spec(FrictionLaw& law, std::string spec) { law.spec_ = std::move(spec); }
  std::string spec_;

  /// Evaluates on validated input.
  [[nodiscard]] virtual FrictionForces do_evaluate(const ContactInput& in) const = 0;
  /// Evaluates validated contacts (equal sizes); by default do_evaluate() on each, in order. An
  /// override gives the same values as do_evaluate(), and at a contact it rejects throws BatchError
  /// with that index after filling `out` before it.
  virtual void do_evaluate_batch(std::span<const ContactInput> in, std::span<FrictionForces> out) const;
};

}  // namespace frictionlab::friction
