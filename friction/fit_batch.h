#pragma once
// `fit` (friction/fit_law.h) over many contacts at once: the per-contact evaluation, and the batch
// that evaluates blocks of contacts across SIMD lanes with the same arithmetic, so that each
// result is the per-contact one bit for bit (FrictionLaw's batch contract, friction/law.h).
//
// How (docs/fit.md, cost): a first pass over the contacts reads each one and does what cannot run
// across lanes, per contact: cos psi and sin psi (from an angle, std::cos and std::sin), the axis
// ratio and its logarithm (no vector logarithm gives the same bits as std::log). Contacts whose
// evaluation takes a rare branch (b/a below 0.01, where E(e) is an arithmetic-geometric-mean
// loop; a Omega beyond the doubles or below the normal ones, where the slip ratio takes two
// divisions) are evaluated there, one by one. The others fill a block in structure-of-arrays form,
// on which one loop computes the geometry (a square root, E's polynomials, seven cubics) and the
// general formula (three square roots, two divisions) of every lane, and a second selects the
// limits (U = 0, Omega = 0) and scales, without a branch. GCC vectorises both at the baseline
// x86-64 instruction set (SSE2, two doubles a lane) given -fno-math-errno (for sqrtpd), which
// friction/CMakeLists.txt sets for this library; -ffp-contract=off there keeps every build
// (-march=native too) from fusing a multiply-add in one path and not the other.

#include <span>

#include "friction/law.h"
#include "friction/standalone/fit_law.h"

namespace frictionlab::friction {

/// `fit` at one validated contact, for pressure `p`: FitLaw's per-contact evaluation.
[[nodiscard]] FrictionForces fit_contact(frictionlab_fit::Pressure p, const ContactInput& in);

/// fit_contact() of each validated contact of `in` into the same position of `out` (equal sizes),
/// bit for bit, several contacts at once. Throws nothing: `fit` rejects no valid contact.
void fit_contacts(frictionlab_fit::Pressure p, std::span<const ContactInput> in, std::span<FrictionForces> out);

}  // namespace frictionlab::friction
