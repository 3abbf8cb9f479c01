#pragma once
// Hertz's elliptic contact of a convex surface with a flat (docs/contact-models.md §2).
//
// A surface with principal radii of curvature R_major >= R_minor at the first point of contact,
// pressed on a flat by the approach delta (m), touches it over an ellipse whose major axis lies
// along the direction of R_major (the smaller curvature). With the relative curvatures
// A = 1/(2 R_major), B = 1/(2 R_minor), mu = b/a, e^2 = 1 - mu^2, K = K(e), E = E(e) and
// D = (K - E)/e^2 (Carlson's forms with the complementary modulus mu, Boost.Math ellint_rd:
// D = R_D(0, mu^2, 1)/3, K - D = mu^2 R_D(0, 1, mu^2)/3, DLMF 19.25.1), Hertz's equations
// (Hertz 1882; Johnson, Contact Mechanics, 1985, §4.2 — docs/contact-models.md gives the sources
// and why no equation numbers) are
//     A = (p0/E*) (b/a^2) D,     B = (p0/E*) (b/a^2) (K - D)/mu^2,     delta = (p0/E*) b K,
//     N = (2/3) pi a b p0,
// so that (exactly, no cancellation as e -> 0)
//     B/A = R_major/R_minor = (K - D)/(mu^2 D)          (the eccentricity equation, solved for mu)
//     a^2 = 2 R_major delta D/K,   b = mu a,   N = (2 pi/3) E* delta a / K = E* S delta^(3/2),
// S = (2 pi/3) sqrt(2 R_major D/K) / K (m^(1/2)). A sphere (mu = 1, D/K = 1/2) gives a^2 = R delta
// and N = (4/3) E* sqrt(R) delta^(3/2) (Johnson §4.2).

namespace frictionlab::dynamics {

/// Radii closer than this (relative) are equal: the patch is a circle, mu = 1 exactly.
inline constexpr double kHertzCircleRelTol = 1e-12;

/// The Hertz ellipse of a surface with principal radii R_major >= R_minor on a flat.
struct HertzEllipse {
  double mu = 1.0;              ///< b/a, in (0, 1]
  double a2_per_depth = 0.0;    ///< a^2/delta = 2 R_major D/K, m
  double stiffness_per_modulus = 0.0;  ///< S = N/(E* delta^1.5), m^(1/2)
  double K = 0.0;               ///< K(e) at the solution
  double D = 0.0;               ///< D(e) = (K - E)/e^2 at the solution
  /// d ln S / d ln R of the first and of the second radius passed to hertz_ellipse (the other one
  /// fixed): how the stiffness changes with the curvatures. Their sum is 1/2 (S ~ sqrt(R)); each
  /// is 1/4 at equal radii.
  double dlnS_dlnR1 = 0.25;
  double dlnS_dlnR2 = 0.25;
};

/// Solves Hertz's eccentricity equation for the principal radii (m, finite, > 0, any order; the
/// major axis lies along the larger), mu to rounding. Throws std::invalid_argument for radii that
/// are not finite and positive. Never allocates.
[[nodiscard]] HertzEllipse hertz_ellipse(double R1, double R2);

/// The curvature ratio B/A = (K - D)/(mu^2 D) that Hertz's ellipse with axis ratio mu in (0, 1]
/// needs (the left side of the eccentricity equation).
[[nodiscard]] double hertz_curvature_ratio(double mu);

/// The effective modulus 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 (Pa; Johnson §4.2's definition
/// of E*). E2 = inf is a rigid plane. Throws std::invalid_argument naming the scenario
/// key (contact.E1, contact.nu1, ...) for E <= 0 or not a number, and nu outside (-1, 0.5].
[[nodiscard]] double effective_modulus(double E1, double nu1, double E2, double nu2);

}  // namespace frictionlab::dynamics
