#include "friction/pade_reconstructed_law.h"

#include <cassert>
#include <cmath>
#include <numbers>

namespace frictionlab::friction {

PatchEllipticIntegrals patch_elliptic_integrals(double mu) {
  assert(mu > 0.0 && mu <= 1.0);
  // AGM of (1, mu) (DLMF 19.8.1-2): a_{n+1} = (a_n + g_n)/2, g_{n+1} = sqrt(a_n g_n),
  // c_{n+1} = c_n^2 / (4 a_{n+1}) with c_0 = k, c_1 = (1 - mu)/2; then K = pi/(2 a_inf) and
  // K - E = K sum_{n>=0} 2^(n-1) c_n^2. The n = 0 term is k^2/2, so
  //   B = 2(K - E)/k^2 - K = (K/k^2) sum_{n>=1} 2^n c_n^2,   C = B/k^2 = K sum_{n>=1} 2^n tau_n^2,
  // with tau_n = c_n/k^2: tau_1 = 1/(2(1 + mu)), tau_{n+1} = k^2 tau_n^2 / (4 a_{n+1}). No
  // difference of nearly equal numbers appears, so B and C keep full relative accuracy at the
  // circle.
  const double k2 = (1.0 - mu) * (1.0 + mu);
  double a = 0.5 * (1.0 + mu);
  double g = std::sqrt(mu);
  double tau = 0.5 / (1.0 + mu);
  double two_n = 2.0;
  double sum = two_n * tau * tau;
  // Stop once c_n <= 1e-9 a_n: then a_n - a_inf ~ c_n^2/(4 a) <= 2.5e-19 a and the next term of the
  // sum is below 1e-18 of this one. mu = 0.05 takes 5 steps, mu = 1e-6 takes 7, mu = 1 none.
  for (int n = 0; n < 64 && k2 * tau > 1e-9 * a; ++n) {
    const double a_next = 0.5 * (a + g);
    g = std::sqrt(a * g);
    a = a_next;
    tau = k2 * tau * tau / (4.0 * a);
    two_n *= 2.0;
    sum += two_n * tau * tau;
  }
  PatchEllipticIntegrals out{};
  out.K = std::numbers::pi / (2.0 * a);
  out.C = out.K * sum;
  out.B = k2 * out.C;
  out.E = out.K * (1.0 - 0.5 * k2) - 0.5 * k2 * out.B;  // from the definition of B
  return out;
}

PadeReconstructedCoefficients pade_reconstructed_coefficients(double mu, const PatchAngle& psi) {
  const auto ell = patch_elliptic_integrals(mu);
  const double k2 = (1.0 - mu) * (1.0 + mu);
  const auto [c, s] = psi.cos_sin();
  const double cos2 = (c - s) * (c + s);
  const double sin2 = 2.0 * s * c;
  const double d3 = k2 * c * c + mu * mu;  // Eq. (9), delta_3 > 0
  const double d4 = k2 * sin2;             // Eq. (9), delta_4
  const double L = ell.K + ell.B * cos2;   // >= K - B = 2(E - mu^2 K)/k^2 > 0
  PadeReconstructedCoefficients out{};
  out.a2 = d3 / 10.0;                      // fast slip of F1 (the printed a2)
  out.a1 = 0.75 * L * out.a2;              // slow-slip slope of F1: a1/a2 = (3/4) L
  out.a3 = d4 / 10.0;                      // fast slip of F2
  out.a4 = 2.0 / (15.0 * ell.C);           // a3/a4 = slow-slip slope (3/4) B sin 2psi
  out.m0_over_alpha_f0 = 0.375 * ell.E;    // exact pure-spin torque
  out.b2 = L / ell.E;                      // slow slip of M: M/M0 = 1 - b2 s^2
  out.b1 = 8.0 * d3 * L / (15.0 * ell.E * ell.E);  // fast slip of M: M0 b1/b2 = d3/5
  return out;
}

std::string_view PadeReconstructedLaw::name() const { return "pade-reconstructed"; }

std::string_view PadeReconstructedLaw::summary() const {
  return "forms (8) of Munitsyna (2013), coefficients re-matched to the exact slow/fast-slip "
         "limits; F2 even, no pole";
}

LawPromises PadeReconstructedLaw::promises() const {
  LawPromises p;
  p.F1_in_Omega = Parity::even;
  p.F2_in_Omega = Parity::even;
  p.M_in_Omega = Parity::odd;
  p.pi_periodic_in_psi = true;
  p.psi_mirror = true;
  p.dissipative = true;
  p.whole_domain = true;
  p.exact_pure_spin = true;
  p.tolerance = 1e-13;  // rounding of closed forms
  return p;
}

FrictionForces PadeReconstructedLaw::do_evaluate(const ContactInput& in) const {
  const double F0 = in.k * in.N;
  if (F0 == 0.0 || (in.U == 0.0 && in.Omega == 0.0)) return {};
  const double mu = in.b / in.a;
  const auto c = pade_reconstructed_coefficients(mu, in.psi);
  if (in.Omega == 0.0) return {F0, 0.0, 0.0};  // pure sliding: the fast side at t = 0
  const double M0 = c.m0_over_alpha_f0 * in.a * F0;
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  const double s = slip_ratio(in.U, in.a, in.Omega);  // U/(alpha|Omega|), alpha = a

  FrictionForces out;
  if (s < 1.0) {
    // Slow side: s in [0, 1). Every denominator is >= its constant term > 0.
    out.F1 = F0 * (s * (s + c.a1)) / (s * (s + c.a1) + c.a2);
    out.F2 = F0 * c.a3 * s / (s * s * s + c.a4);
    out.M = sign * M0 * (1.0 + c.b1 * s) / (1.0 + s * (c.b1 + c.b2 * s));
  } else {
    // Fast side: t = alpha|Omega|/U in [0, 1]. The same rational functions in 1/s.
    const double t = 1.0 / s;
    out.F1 = F0 * (1.0 + c.a1 * t) / (1.0 + t * (c.a1 + c.a2 * t));
    out.F2 = F0 * c.a3 * t * t / (1.0 + c.a4 * t * t * t);
    out.M = sign * M0 * t * (t + c.b1) / (c.b2 + t * (c.b1 + t));
  }
  return out;
}

}  // namespace frictionlab::friction
