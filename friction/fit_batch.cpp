#include "friction/fit_batch.h"

#include <cmath>
#include <cstddef>

namespace frictionlab::friction {
namespace {

// The smallest normal and the largest finite double (the bounds frictionlab_fit::evaluate tests).
constexpr double kSmallestNormal = 2.2250738585072014e-308;
constexpr double kLargest = 1.7976931348623157e308;
// Below this axis ratio frictionlab_fit::elliptic_e leaves its polynomial fit for a loop.
constexpr double kEllipticFitMinAxisRatio = 0.01;

// Contacts per block: a multiple of every SIMD width (2 doubles with SSE2, 4 with AVX, 8 with
// AVX-512), small enough that the block stays in the L1 cache (~2 KB), large enough that the
// loops' fixed cost is spread (32 was no faster).
constexpr std::size_t kBlock = 16;

// A block of contacts that take the common path, one array per quantity, so that the loop over the
// lanes reads and writes each quantity contiguously.
struct Block {
  double U[kBlock], w[kBlock], a[kBlock], mu[kBlock], ln_mu[kBlock], c[kBlock], s[kBlock], kN[kBlock];
  double F1[kBlock], F2[kBlock], M[kBlock], M0[kBlock];  // per kN and kNa, then N and N m
  std::size_t index[kBlock];  // the contact's position in the batch
};

// The lanes of `b`, each as frictionlab_fit::make_geometry then frictionlab_fit::evaluate on its
// common path (E by its fit, a Omega a normal double or 0), in the same operations, without a
// branch. Two loops: the first computes every lane's general formula, the second selects the
// limits of frictionlab_fit::unit_forces (U = 0, Omega = 0) and scales. In one loop GCC moves the
// general formula under the test of the limits and then, since a division or a square root may
// raise a floating-point exception (-ftrapping-math, the default), will not compute it in every
// lane: the loop is not vectorised. In a lane at a limit the general formula divides by 0; its NaN
// is not selected. The pressure is a template parameter: its fitted numbers are then constants,
// not loads the vectoriser cannot place.
template <int p>
void evaluate_lanes(Block& b) {
  for (std::size_t i = 0; i < kBlock; ++i) {
    const double mu = b.mu[i];
    const frictionlab_fit::Geometry g =
        frictionlab_fit::detail::geometry_from_e(mu, frictionlab_fit::elliptic_e_fit(mu * mu, b.ln_mu[i]), p);
    const double u = b.U[i], w = b.w[i];
    const double aw = std::fabs(w);
    const double largest = u > aw ? u : aw;
    const double inv = 1.0 / largest;  // largest >= aw is normal when the contact spins
    const frictionlab_fit::Forces moving =
        frictionlab_fit::detail::moving_unit_forces(g, u * inv, w * inv, b.c[i], b.s[i]);
    b.F1[i] = moving.F1;
    b.F2[i] = moving.F2;
    b.M[i] = moving.M;
    b.M0[i] = g.M0;
  }
  for (std::size_t i = 0; i < kBlock; ++i) {
    const double u = b.U[i], w = b.w[i];
    // Each test made in every lane: an ordered comparison may raise a floating-point exception
    // too, so one made only under another would again be a branch.
    const bool sliding = w == 0.0, still = u == 0.0, forward = u > 0.0, positive = w > 0.0;
    const bool general = !sliding && !still;
    const double slide_F1 = forward ? 1.0 : 0.0;    // Omega = 0: F1 = kN if it moves
    const double spin_M = positive ? b.M0[i] : -b.M0[i];  // U = 0: M = +-kNa M0
    const double F1 = general ? b.F1[i] : (sliding ? slide_F1 : 0.0);
    const double F2 = general ? b.F2[i] : 0.0;
    const double M = general ? b.M[i] : (sliding ? 0.0 : spin_M);
    const double kN = b.kN[i];
    b.F1[i] = kN * F1;
    b.F2[i] = kN * F2;
    b.M[i] = kN * b.a[i] * M;
  }
}

}  // namespace

FrictionForces fit_contact(frictionlab_fit::Pressure p, const ContactInput& in) {
  const PatchAngle::CosSin axis = in.psi.cos_sin();
  const frictionlab_fit::Geometry g = frictionlab_fit::make_geometry(in.b / in.a, p);
  const frictionlab_fit::Forces f = frictionlab_fit::evaluate(g, in.U, in.Omega, in.a, axis.c, axis.s, in.N, in.k);
  return {f.F1, f.F2, f.M};
}

void fit_contacts(frictionlab_fit::Pressure p, std::span<const ContactInput> in, std::span<FrictionForces> out) {
  Block b;
  std::size_t lanes = 0;
  const auto flush = [&] {
    // A partial block is filled with copies of its first lane, whose results are not read.
    for (std::size_t i = lanes; i < kBlock; ++i) {
      b.U[i] = b.U[0], b.w[i] = b.w[0], b.a[i] = b.a[0], b.mu[i] = b.mu[0], b.ln_mu[i] = b.ln_mu[0];
      b.c[i] = b.c[0], b.s[i] = b.s[0], b.kN[i] = b.kN[0];
    }
    switch (p) {
      case frictionlab_fit::Pressure::hertz: evaluate_lanes<0>(b); break;
      case frictionlab_fit::Pressure::uniform: evaluate_lanes<1>(b); break;
      case frictionlab_fit::Pressure::punch: evaluate_lanes<2>(b); break;
    }
    for (std::size_t i = 0; i < lanes; ++i) out[b.index[i]] = {b.F1[i], b.F2[i], b.M[i]};
    lanes = 0;
  };
  for (std::size_t j = 0; j < in.size(); ++j) {
    const ContactInput& c = in[j];
    const double mu = c.b / c.a;
    const double w = c.a * c.Omega;
    const double aw = std::fabs(w);
    // frictionlab_fit::evaluate's test for its common path, and elliptic_e's.
    const bool scaled = aw <= kLargest && (aw >= kSmallestNormal || c.Omega == 0.0);
    if (!scaled || !(mu >= kEllipticFitMinAxisRatio)) {
      out[j] = fit_contact(p, c);
      continue;
    }
    const PatchAngle::CosSin axis = c.psi.cos_sin();
    b.U[lanes] = c.U;
    b.w[lanes] = w;
    b.a[lanes] = c.a;
    b.mu[lanes] = mu;
    b.ln_mu[lanes] = std::log(mu);
    b.c[lanes] = axis.c;
    b.s[lanes] = axis.s;
    b.kN[lanes] = c.k * c.N;
    b.index[lanes] = j;
    if (++lanes == kBlock) flush();
  }
  if (lanes > 0) flush();
}

}  // namespace frictionlab::friction
