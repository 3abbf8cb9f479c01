// frictionlab `fit`: a closed-form law of coupled dry friction (sliding + spinning) on an elliptic
// contact patch, dissipative and free of poles for every input by construction. One header, no
// dependency but the C++ standard library (C++11 or later): an engine may copy it as it is.
// Part of frictionlab, MIT licence (Copyright (c) 2026 The frictionlab authors); the derivation,
// the fit and its measured accuracy are in frictionlab's docs/fit.md.
//
// WHAT IT COMPUTES. A patch with semi-axes a >= b > 0 (mu = b/a) slides at speed U >= 0 along e1
// and spins at Omega about the upward normal gamma; psi is the angle from e1 to the major axis,
// counter-clockwise about gamma. The law returns F1, F2, M: the friction force on the body is
// -F1 e1 - F2 e2 and the friction torque about the patch centre is -M gamma (kN = k*N, the
// friction coefficient times the normal force; kNa = k*N*a).
//
// THE FORM (docs/fit.md §2). In the patch axes, with x = (ux, uy, w) = (U cos psi, -U sin psi,
// a Omega), X = ux^2, Y = uy^2, W = w^2, S = X + Y,
//
//   P(X, Y, W) = S^4 + 4 W S^2 m2 (X + mu^2 Y) + W^2 (c0 X^2 + c1 X Y + c2 Y^2)
//              + W^3 (c3 X + c4 Y) + M0^8 W^4,
//   D = P^(1/8)  (the dissipation per kN: homogeneous of degree one in x),
//   (F_major, F_minor, M/a) = kN grad D = kN D/(4P) (ux P_X, uy P_Y, w P_W),
//
// m2 the pressure's second moment per axis, M0 = c_p E(e) the exact pure-spin moment per kNa
// (e^2 = 1 - mu^2, c_p = 3/8 Hertz, 4/(3 pi) uniform, 1/2 flat punch), and, with z = sqrt(mu) and
// t = 1 - z,
//
//   c0 = A^2 + t B0^2,  c1 = 2 A^2 + t B1^2,  c2 = A^2 + t B2^2,  c3 = C^2 + t B3^2,  c4 = C^2 + t B4^2,
//
// A, C, B0..B4 cubic polynomials in z: 28 fitted numbers per pressure (detail::kQ below). At
// mu = 1 (t = 0) P depends on S and W only: a circle has no preferred direction, as the exact law.
//
// WHAT HOLDS FOR EVERY INPUT, whatever the fitted numbers (each c_m is a sum of squares):
//   * no pole: every term of P is >= 0 and P >= S^4 + M0^8 W^4 > 0 when the contact moves;
//   * dissipative: F1 U + M Omega = kN D(x) >= 0 (Euler's theorem for a degree-one D);
//   * pure spin (U = 0) exact: F1 = F2 = 0, M = c_p kNa E(e) sign(Omega);
//   * pure sliding (Omega = 0): F1 = kN, F2 = M = 0; fast slip exact to the first order that
//     matters: M -> kNa m2 d3/s, 1 - F1/kN -> m2 d3/(2 s^2), F2/kN -> m2 d4/(2 s^2) (s = U/(a|Omega|),
//     d3 = e^2 cos^2 psi + mu^2, d4 = 2 e^2 sin psi cos psi);
//   * F1, F2 even and M odd in Omega; psi -> psi + pi changes nothing; psi -> -psi flips F2 only;
//     a circle (mu = 1): F2 = 0 and psi plays no part;
//   * the result depends on U and a Omega through their ratio only, scaled so that nothing
//     overflows or underflows.
// |F| <= kN and |M| <= M0 kNa hold if D is convex: checked numerically, not proven (docs/fit.md).
//
// ACCURACY against the exact law (the Coulomb traction integrated over the patch), per kN for the
// forces and per kNa for the moment, for mu in [0.05, 1], every s and psi: largest errors on
// 120,000 seeded points per pressure (docs/fit.md §4, frictionlab's tests/friction/fit_law_test.cpp):
// kMaxError below. Below mu = 0.05 the fitted polynomials extrapolate: every
// property above still holds, the accuracy is not measured.
//
// USE. Once per contact shape (mu and the pressure model), then per evaluation:
//
//   const frictionlab_fit::Geometry g = frictionlab_fit::make_geometry(b / a, frictionlab_fit::Pressure::hertz);
//   const frictionlab_fit::Forces f = frictionlab_fit::evaluate(g, U, Omega, a, cos_psi, sin_psi, N, k);
//
// The coefficients were fitted by frictionlab's friction/tools/fit_dissipation.py.

#ifndef FRICTIONLAB_STANDALONE_FIT_LAW_H
#define FRICTIONLAB_STANDALONE_FIT_LAW_H

#include <cmath>

namespace frictionlab_fit {

/// The pressure over the patch: Hertz (ellipsoidal), uniform, flat punch.
enum class Pressure { hertz = 0, uniform = 1, punch = 2 };

/// The friction on the body: force -F1 e1 - F2 e2 (N), torque -M gamma (N m).
struct Forces {
  double F1;
  double F2;
  double M;
};

/// Largest errors found against the exact law, per kN (forces) and per kNa (moment), mu in
/// [0.05, 1], all s and psi (docs/fit.md §4), indexed by Pressure.
constexpr double kMaxError[3] = {0.042, 0.045, 0.061};

namespace detail {

// The fitted numbers q[pressure][r][i] of the polynomials sum_i q_ri z^i, z = sqrt(mu), in the
// order r = A, C, B0, B1, B2, B3, B4 (friction/tools/fit_dissipation.py).
constexpr double kQ[3][7][4] = {
    {
        // hertz
        {0.18264592661255602, 0.21319352478553935, -0.63584554733275311, 0.83221210641215415},
        {0.070625257132867103, 0.18626547074814226, -0.55478647712900198, 0.64510273798313278},
        {0.079311684607179495, 2.3548679559309385, -3.6216260213821831, 2.1846479490350048},
        {0.45652850391888045, 1.2438259072517261, -2.4477228714476582, 1.6060484582818284},
        {-0.0051523437500000015, -0.031152343749999995, -0.031152343750000019, -0.031152343749999988},
        {0.10775256490789661, 0.10539255944483586, -0.45090907164182531, 0.34721887527941991},
        {0.032152343750000006, -0.031152343749999995, -0.031152343750000019, -0.031152343749999988},
    },
    {
        // uniform
        {-0.51737542140196502, 3.4898245286756882, -5.3627476791802717, 2.9797288278904999},
        {-0.31772465548599343, 1.9879333373092121, -3.108830253929928, 1.9835076537602343},
        {0.65595907182986246, -0.73816223064104503, 3.9653002865272344, -3.5110560854868402},
        {0.41733590938769838, 4.2623510564288649, -10.861845144937723, 8.3138146796228884},
        {-0.0054997503579861029, 2.7506317140125338, -7.8782082371844488, 5.7872421227791842},
        {0.049258470479825275, 1.5240624066900359, -4.0931298330716244, 2.9394736032433566},
        {-0.019142210287101984, 1.5868536404540718, -4.3799807812776059, 3.4280584908512726},
    },
    {
        // punch
        {-0.81577676680219813, 4.886429673768947, -7.4414475314162827, 4.2329153037695377},
        {0.18336088792417096, 0.37535884053582014, -1.054203899843865, 1.3679240731181568},
        {0.73131960391804063, -0.1511619205303901, 4.357385439669339, -4.3600117489005656},
        {0.49045428364906857, 5.7213455017051746, -13.746287719095166, 10.329275160509692},
        {0.46129018781484399, -6.0468843626094113, 15.264203115178098, -10.616921109309558},
        {0.031027016246085701, 1.5936135838653751, -3.7952394390723363, 2.2718576569520978},
        {0.087153669970442091, 0.12026361440497493, -1.5306230491932129, 1.3778156341478109},
    },
};

// The pure-spin factor c_p (M0 = c_p E(e)) and the second moment m2 per axis of each pressure
// (frictionlab's docs/pressure-models.md).
constexpr double kPureSpinFactor[3] = {0.375, 0.42441318157838759, 0.5};
constexpr double kSecondMoment[3] = {0.2, 0.25, 1.0 / 3.0};

}  // namespace detail

/// E(e), e^2 = 1 - mu^2, for mu in [0.01, 1] from m1 = mu^2 and ln_mu = ln(mu), as
/// P(m1) - ln(m1) Q(m1) (the form of E's expansion about e = 1): largest relative error 1.26e-14
/// (frictionlab's friction/tools/fit_elliptic_e.py, which fitted the coefficients). Outside
/// [0.01, 1] it is not E: use elliptic_e().
inline double elliptic_e_fit(double m1, double ln_mu) {
  // P: m1^0..m1^8.
  const double p0 = 1.00000000000000777e+00, p1 = 4.43147181230792719e-01, p2 = 5.68057124381813883e-02,
               p3 = 2.18795455451062382e-02, p4 = 1.25520758471495131e-02, p5 = 1.31434886966174114e-02,
               p6 = 1.53560065109186183e-02, p7 = 7.22247542904486117e-03, p8 = 6.89841097086238420e-04;
  // Q: m1^1..m1^8.
  const double q1 = 2.49999999922726146e-01, q2 = 9.37499101465794765e-02, q3 = 5.85819356802619109e-02,
               q4 = 4.23649618275207390e-02, q5 = 3.02039742932201268e-02, q6 = 1.53627745531750171e-02,
               q7 = 3.41316878843145322e-03, q8 = 1.59278550086593140e-04;
  const double x = m1;
  const double P = p0 + x * (p1 + x * (p2 + x * (p3 + x * (p4 + x * (p5 + x * (p6 + x * (p7 + x * p8)))))));
  const double Q = x * (q1 + x * (q2 + x * (q3 + x * (q4 + x * (q5 + x * (q6 + x * (q7 + x * q8)))))));
  return P - 2.0 * ln_mu * Q;
}

/// E(e), e^2 = 1 - mu^2, for every mu in (0, 1]: the fit on [0.01, 1], the arithmetic-geometric
/// mean below (Abramowitz & Stegun 17.6), to full double precision.
inline double elliptic_e(double mu) {
  if (mu >= 0.01) return elliptic_e_fit(mu * mu, std::log(mu));
  double a = 1.0, b = mu, sum = 0.5 * (1.0 - mu * mu), weight = 0.5;
  for (int i = 0; i < 64 && a - b > 1e-15 * a; ++i) {
    const double c = 0.5 * (a - b);
    const double a_next = 0.5 * (a + b);
    b = std::sqrt(a * b);
    a = a_next;
    weight *= 2.0;
    sum += weight * c * c;
  }
  return 3.14159265358979323846 / (2.0 * a) * (1.0 - sum);
}

/// What the law needs of a patch's shape: computed once per contact shape (mu and the pressure).
struct Geometry {
  double mu2;   ///< mu^2
  double m2;    ///< the pressure's second moment per axis
  double M0;    ///< c_p E(e): the pure-spin moment per kNa
  double M8;    ///< M0^8
  double c[5];  ///< the fitted coefficients at this mu
};

namespace detail {

/// (q0 + q1 z + q2 z^2 + q3 z^3)^2.
inline double squared_cubic(const double* q, double z) {
  const double root = q[0] + z * (q[1] + z * (q[2] + z * q[3]));
  return root * root;
}

/// The geometry of a patch with axis ratio mu and E(e) = e_of_mu, pressure index p: make_geometry
/// without the choice of E's route, branch-free, so that a loop over many contacts vectorises
/// (frictionlab's friction/fit_batch.cpp evaluates through it, bit for bit as make_geometry).
inline Geometry geometry_from_e(double mu, double e_of_mu, int p) {
  Geometry g;
  const double z = std::sqrt(mu);
  const double t = 1.0 - z;
  // The squares of the seven cubics, written out rather than looped over: a loop inside would keep
  // a loop over contacts from vectorising.
  const double A = squared_cubic(kQ[p][0], z), C = squared_cubic(kQ[p][1], z);
  const double B0 = squared_cubic(kQ[p][2], z), B1 = squared_cubic(kQ[p][3], z), B2 = squared_cubic(kQ[p][4], z);
  const double B3 = squared_cubic(kQ[p][5], z), B4 = squared_cubic(kQ[p][6], z);
  g.c[0] = A + t * B0;
  g.c[1] = 2.0 * A + t * B1;
  g.c[2] = A + t * B2;
  g.c[3] = C + t * B3;
  g.c[4] = C + t * B4;
  g.mu2 = mu * mu;
  g.m2 = kSecondMoment[p];
  g.M0 = kPureSpinFactor[p] * e_of_mu;
  const double M2 = g.M0 * g.M0;
  const double M4 = M2 * M2;
  g.M8 = M4 * M4;
  return g;
}

/// The law per kN and kNa of a moving contact (unit_forces below, past its limits): un > 0 and
/// wn != 0 the slip and spin speeds scaled so that the larger is 1. Branch-free, for the same
/// reason as geometry_from_e.
inline Forces moving_unit_forces(const Geometry& g, double un, double wn, double cos_psi, double sin_psi) {
  const double ux = un * cos_psi, uy = -un * sin_psi;
  const double X = ux * ux, Y = uy * uy, W = wn * wn, S = X + Y;
  const double J = g.m2 * (X + g.mu2 * Y);
  const double W2 = W * W, W3 = W2 * W, S2 = S * S;
  const double A2 = g.c[0] * X * X + g.c[1] * X * Y + g.c[2] * Y * Y;  // the W^2 block
  const double A3 = g.c[3] * X + g.c[4] * Y;                           // the W^3 block
  const double P = S2 * S2 + 4.0 * W * S2 * J + W2 * A2 + W3 * A3 + g.M8 * W2 * W2;
  const double PX = 4.0 * S2 * S + 4.0 * W * (2.0 * S * J + S2 * g.m2) + W2 * (2.0 * g.c[0] * X + g.c[1] * Y) +
                    W3 * g.c[3];
  const double PY = 4.0 * S2 * S + 4.0 * W * (2.0 * S * J + S2 * g.m2 * g.mu2) +
                    W2 * (g.c[1] * X + 2.0 * g.c[2] * Y) + W3 * g.c[4];
  const double PW = 4.0 * S2 * J + 2.0 * W * A2 + 3.0 * W2 * A3 + 4.0 * g.M8 * W3;
  const double D = std::sqrt(std::sqrt(std::sqrt(P)));  // P^(1/8)
  const double f = D / (4.0 * P);
  const double Gx = f * ux * PX, Gy = f * uy * PY;  // along the major and the minor axis
  Forces out;
  out.F1 = Gx * cos_psi - Gy * sin_psi;
  out.F2 = Gx * sin_psi + Gy * cos_psi;
  out.M = f * wn * PW;
  return out;
}

}  // namespace detail

/// The geometry of a patch with axis ratio mu = b/a in (0, 1] (fitted on [0.05, 1]).
inline Geometry make_geometry(double mu, Pressure pressure) {
  return detail::geometry_from_e(mu, elliptic_e(mu), static_cast<int>(pressure));
}

/// The law per kN and kNa: u >= 0 the slip speed and w the signed spin speed a Omega, in any common
/// unit (only u/|w| matters), (cos_psi, sin_psi) the major axis's direction in (e1, e2), a unit
/// vector. Returns F1/(kN), F2/(kN), M/(kNa). At u = w = 0 the law is set-valued: it returns 0.
/// An infinite u is pure sliding, an infinite w (with u finite) pure spin.
inline Forces unit_forces(const Geometry& g, double u, double w, double cos_psi, double sin_psi) {
  Forces out = {0.0, 0.0, 0.0};
  if (w == 0.0 || std::isinf(u)) {
    if (u > 0.0) out.F1 = 1.0;  // pure sliding
    return out;
  }
  if (u == 0.0 || std::isinf(w)) {  // pure spin
    out.M = w > 0.0 ? g.M0 : -g.M0;
    return out;
  }
  // Scale x so that max(u, |w|) = 1: P then lies in [min(1, M0^8)/256, 256], no overflow. One
  // reciprocal, no branch on which is larger (it would be mispredicted half the time); below the
  // normal doubles the reciprocal would overflow, so there two divisions.
  const double aw = std::fabs(w);
  const double largest = u > aw ? u : aw;
  double un, wn;
  if (largest >= 2.2250738585072014e-308) {
    const double inv = 1.0 / largest;
    un = u * inv;
    wn = w * inv;
  } else {
    un = u / largest;
    wn = w / largest;
  }
  return detail::moving_unit_forces(g, un, wn, cos_psi, sin_psi);
}

/// The law in SI units: U >= 0 slip speed (m/s), Omega spin (1/s), a the major semi-axis (m),
/// (cos_psi, sin_psi) the major axis's direction in (e1, e2), N the normal force (N), k the
/// friction coefficient; all finite. Returns F1, F2 (N) and M (N m): finite whenever k N and
/// k N a are.
inline Forces evaluate(const Geometry& g, double U, double Omega, double a, double cos_psi, double sin_psi, double N,
                       double k) {
  const double kN = k * N;
  const double w = a * Omega;
  const double aw = std::fabs(w);
  // a Omega beyond the doubles, or below the normal ones while Omega is not 0: the slip ratio
  // U/(a |Omega|) by two divisions, which neither overflow nor underflow spuriously.
  const bool scaled = aw <= 1.7976931348623157e308 && (aw >= 2.2250738585072014e-308 || Omega == 0.0);
  const Forces unit = scaled ? unit_forces(g, U, w, cos_psi, sin_psi)
                             : unit_forces(g, (U / a) / std::fabs(Omega), Omega > 0.0 ? 1.0 : -1.0, cos_psi, sin_psi);
  const Forces out = {kN * unit.F1, kN * unit.F2, kN * a * unit.M};
  return out;
}

}  // namespace frictionlab_fit

#endif  // FRICTIONLAB_STANDALONE_FIT_LAW_H
