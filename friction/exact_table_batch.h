#pragma once
// `exact-table` (friction/exact_table_law.h) over many contacts at once: the per-contact evaluation,
// and the batch that runs the same steps over blocks of contacts, so that each result is the
// per-contact one bit for bit (FrictionLaw's batch contract, friction/law.h).
//
// How (docs/exact-table.md §7): one pass over the contacts does, per contact, everything before the
// table's sum: the limits (N = 0, k = 0, Omega = 0, U = 0, s = inf, s > 1e8; their results are
// written at once), cos psi and sin psi, ln(b/a), the pure-spin moment, the table's coordinates and
// cell (steps 4-7 of docs/exact-table.md, ExactTable::locate). A contact on the table's path joins
// a block of 16; a full block is then summed (weights, the 288 multiply-adds, step 9). Called one
// by one, a contact's sum waits for its cell (a chain of square roots, divisions, a logarithm)
// before it can load a row; in a block every row address is known before the first sum starts.
// Where the processor has AVX (checked at run time: the build targets any x86-64), the block is
// summed two contacts at a time in 4-lane vectors (ExactTable::contract_pair_wide, the same values):
// one contact's sum is a chain of dependent adds, two keep twice as many in flight.
// Measured (docs/exact-table.md §7): the blocks alone (SSE2) ~0.85 of the per-contact loop, with
// the AVX pairs ~0.77.
//
// Tried and left out, having measured no gain: prefetching each cell's 24 rows as it is located
// (slower: 72 prefetch instructions a contact, and the rows come from L3 anyway); the spline
// weights computed across the block's contacts in SIMD lanes (GCC vectorised the loop; no faster
// than per contact); the sum with lanes = contacts (SSE2 has no gather: each coefficient loaded
// singly, as many multiplies and adds as the sum within a contact, which already fills two lanes,
// and twice the loads). Also not done: the coordinates across lanes (both of the table's blocks
// in every lane, and a logarithm per contact outside; about a fifth of the cost). -ffp-contract=off
// on the library (friction/CMakeLists.txt) keeps a build with FMA from fusing in one path and not
// the other.

#include <span>

#include "friction/law.h"
#include "friction/pressure.h"

namespace frictionlab::friction {

/// `exact-table` at one validated contact: ExactTableLaw's per-contact evaluation.
[[nodiscard]] FrictionForces exact_table_contact(Pressure pressure, const ContactInput& in);

/// exact_table_contact() of each validated contact of `in` into the same position of `out` (equal
/// sizes), bit for bit, several contacts at once. At a contact it rejects (b/a < 0.01) it throws
/// BatchError with that index, `out` filled before it.
void exact_table_contacts(Pressure pressure, std::span<const ContactInput> in, std::span<FrictionForces> out);

}  // namespace frictionlab::friction
