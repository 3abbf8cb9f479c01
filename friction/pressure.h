#pragma once
// Normal pressure models over the elliptic contact patch (docs/pressure-models.md):
//
//   p(x, y) = (n + 1) N / (pi a b) (1 - x^2/a^2 - y^2/b^2)^n,
//
// normalised so that its integral over the patch is N, for three exponents:
//   * hertz   n = 1/2   elastic bodies (Hertz): p vanishes at the rim like a square root;
//   * uniform n = 0     a flat rigid face on a soft layer, the classical Contensou-Erismann setting;
//   * punch   n = -1/2  a rigid flat punch on an elastic half-space (Boussinesq): p grows like
//                       1/sqrt(distance) at the rim, an integrable singularity.
// The exact law and its reference take one of them (spec key `pressure`, default hertz).

#include <string>
#include <string_view>
#include <vector>

namespace frictionlab::friction {

enum class Pressure { hertz, uniform, punch };

/// The spec value of a pressure model: "hertz", "uniform", "punch".
[[nodiscard]] std::string_view pressure_name(Pressure p);

/// Every pressure model by name, Hertz first (the default).
[[nodiscard]] std::vector<std::string> pressure_names();

/// The pressure model called `name`; std::invalid_argument naming the value and the choices.
[[nodiscard]] Pressure parse_pressure(std::string_view name);

/// The exponent n of (1 - x^2/a^2 - y^2/b^2)^n: 1/2, 0, -1/2.
[[nodiscard]] double pressure_exponent(Pressure p);

/// The second moment per axis, <x^2>/a^2 = <y^2>/b^2 = 1/(2(n + 2)): Hertz 1/5, uniform 1/4,
/// punch 1/3. It sets the fast-slip expansion (docs/pressure-models.md).
[[nodiscard]] double pressure_second_moment(Pressure p);

/// The pure-spin torque factor c: M = c k N a E(e) at U = 0, E the complete elliptic integral of
/// the second kind of modulus e = sqrt(1 - b^2/a^2): Hertz 3/8, uniform 4/(3 pi), punch 1/2.
[[nodiscard]] double pressure_pure_spin_factor(Pressure p);

}  // namespace frictionlab::friction
