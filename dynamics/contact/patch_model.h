#pragma once
// Which contact model a scenario asks for, `[contact] patch` (docs/contact-models.md §4), and how
// its stiffness is fixed: the paper's section hypothesis with `lambda` (the default), or Hertz's
// theory with the effective modulus from the elastic constants (`E1, nu1, E2, nu2`) or matched
// to `lambda` at a reference orientation (`lambda_gamma3`, default 1: the lower pole).

#include <optional>
#include <string>

#include "dynamics/body/body.h"
#include "dynamics/contact/hertz_contact.h"

namespace frictionlab::dynamics {

/// [contact] keys of the contact model, as written.
struct PatchModelSpec {
  std::string patch = "section";       ///< "section" or "hertz"
  std::optional<double> lambda;        ///< N/m^1.5
  std::optional<double> E1, nu1;       ///< body: Young's modulus (Pa; inf: rigid), Poisson's ratio
  std::optional<double> E2, nu2;       ///< plane: the same
  std::optional<double> lambda_gamma3; ///< gamma3 in [-1, 1] where Hertz's stiffness is `lambda`
};

/// Sets contact.patch, contact.lambda and contact.E_star from `spec` for `body`:
/// * section: `lambda` required; no elastic constants, no lambda_gamma3.
/// * hertz with E1, nu1, E2, nu2 (all four, and no `lambda`): E* from them (Johnson §4.2),
///   lambda = Hertz's stiffness at lambda_gamma3;
/// * hertz without them: `lambda` required, E* such that Hertz's stiffness at lambda_gamma3 is lambda.
/// Errors (std::invalid_argument, support::InvalidValue) name the key and the rule. A lambda that
/// is not finite and positive is left for PlaneContact::validate to report.
void apply_patch_model(const PatchModelSpec& spec, const Body& body, PlaneContact& contact);

}  // namespace frictionlab::dynamics
