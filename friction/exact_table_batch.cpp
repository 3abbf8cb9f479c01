#include "friction/exact_table_batch.h"

#include <cmath>
#include <cstddef>
#include <exception>
#include <stdexcept>
#include <string>

#include "friction/exact_table.h"
#include "friction/support/number_format.h"
#include "friction/uniform_bspline.h"

namespace frictionlab::friction {
namespace {

// Above this slip ratio the law returns the fast-slip expansion, as `exact` does above the same
// ratio (friction/exact_law.cpp): the table would be as good there, but its outside block squares
// the ICR's coordinates, which leave the double range beyond s ~ 1e154.
constexpr double kFastSlipRatio = 1e8;

// A contact on the table's path: where the table is read (steps 5-8 of docs/exact-table.md), and
// what turns its value into forces (step 9).
struct ExactTableContact {
  const ExactTable* table;
  double Xt, Yt;       // the ICR in the patch axes, units of a
  double mu, ln_mu;    // b/a and its logarithm
  double c, sn;        // cos psi, sin psi (1, 0 for a circle)
  double kN;           // k N
  double spin_moment;  // sign(Omega) k N a M0
};

// The steps of the per-contact evaluation before the table is read, at one validated contact: true
// with `done` set if the contact is a limit (no table), false with `pending` set otherwise. Throws
// std::invalid_argument for b/a below the table (0.01). Inlined where it is called: through memory,
// `pending` measured ~5 % slower per call.
[[gnu::always_inline]] inline bool exact_table_begin(Pressure pressure, const ContactInput& in, FrictionForces& done,
                                                     ExactTableContact& pending) {
  const double mu = in.b / in.a;
  if (mu < kExactTableMinAxisRatio) {
    throw std::invalid_argument("friction input b = " + support::shortest(in.b) +
                                " is invalid for exact-table: the axis ratio b/a = " + support::shortest(mu) +
                                " is below " + support::significant(kExactTableMinAxisRatio, 3) +
                                ", where its table ends (use exact)");
  }
  const double kN = in.k * in.N;
  done = {};
  if (kN == 0.0) return true;
  if (in.Omega == 0.0) {
    if (in.U == 0.0) return true;  // indeterminate at U = Omega = 0: zero, as exact
    done = {kN, 0.0, 0.0};         // pure sliding
    return true;
  }
  const double sign = in.Omega > 0.0 ? 1.0 : -1.0;
  const double s = slip_ratio(in.U, in.a, in.Omega);
  if (std::isinf(s)) {  // pure sliding: U/(a|Omega|) beyond the doubles
    done = {kN, 0.0, 0.0};
    return true;
  }
  const double kNa = kN * in.a;
  // A circle is symmetric under rotation: psi = 0 makes F2 = 0 exact.
  const PatchAngle::CosSin axis = (mu == 1.0) ? PatchAngle::CosSin{1.0, 0.0} : in.psi.cos_sin();
  const double c = axis.c;
  const double sn = axis.s;

  if (s > kFastSlipRatio) {
    // Fast-slip expansion (docs/model.md, docs/pressure-models.md), m2 the second moment per axis.
    const double m2 = pressure_second_moment(pressure);
    const double d3 = (1.0 - mu) * (1.0 + mu) * c * c + mu * mu;
    const double d4 = 2.0 * (1.0 - mu) * (1.0 + mu) * sn * c;
    const double is = 1.0 / s;
    done = {kN * (1.0 - 0.5 * m2 * d3 * is * is), kN * 0.5 * m2 * d4 * is * is, sign * kNa * m2 * d3 * is};
    return true;
  }

  // The table design of docs/exact-table.md, "Evaluation, in order".
  const ExactTable& table = ExactTable::of(pressure);
  const double ln_mu = std::log(mu);
  const double M0 = table.pure_spin_moment(mu, ln_mu);  // step 4
  if (s == 0.0) {                                       // pure spin: the table's centre, m = 1
    done = {0.0, 0.0, sign * kNa * M0};
    return true;
  }
  pending = {&table, s * sn, s * c, mu, ln_mu, c, sn, kN, sign * kNa * M0};
  return false;
}

// The forces of a contact on the table's path from the table's value there (step 9).
[[gnu::always_inline]] inline FrictionForces exact_table_end(const ExactTableContact& contact,
                                                             const ExactTableValue& g) {
  // G back to the slip frame.
  const double F1 = -(g.gx * contact.sn + g.gy * contact.c);
  const double F2 = g.gx * contact.c - g.gy * contact.sn;
  return {contact.kN * F1, contact.kN * F2, contact.spin_moment * g.m};
}

// Contacts per block: enough that the sums of a block wait on nothing (their rows' addresses are all
// known when the first starts), few enough that the block's cells stay in L1 (16 x 88 bytes).
constexpr std::size_t kBlock = 16;

// A block of contacts on the table's path, located, waiting for their sums.
struct Block {
  ExactTableContact contact[kBlock];
  ExactTableCell cell[kBlock];
  std::size_t index[kBlock];  // the contact's position in the batch
};

// The weights, tensor sums and forces of the first `lanes` contacts of `b`, into `out`: the steps
// of exact_table_contact() after exact_table_begin(), two contacts' sums at once in AVX where the
// processor has it (`wide`; the same values), the odd one out as exact_table_contact() does it.
void sum_block(const Block& b, std::size_t lanes, bool wide, std::span<FrictionForces> out) {
  std::size_t i = 0;
  if (wide) {
    for (; i + 1 < lanes; i += 2) {
      const ExactTableContact& c0 = b.contact[i];
      const ExactTableContact& c1 = b.contact[i + 1];
      ExactTableValue g0;
      ExactTableValue g1;
      ExactTable::contract_pair_wide(b.cell[i], b.cell[i + 1], g0, g1);
      out[b.index[i]] = exact_table_end(c0, g0);
      out[b.index[i + 1]] = exact_table_end(c1, g1);
    }
  }
  for (; i < lanes; ++i) {
    const ExactTableCell& cell = b.cell[i];
    double wt[6];
    double wx[4];
    double wz[4];
    exact_table_weights(cell, wt, wx, wz);
    out[b.index[i]] = exact_table_end(b.contact[i], ExactTable::contract(cell, wt, wx, wz));
  }
}

}  // namespace

FrictionForces exact_table_contact(Pressure pressure, const ContactInput& in) {
  FrictionForces done;
  ExactTableContact pending;
  if (exact_table_begin(pressure, in, done, pending)) return done;
  return exact_table_end(pending, pending.table->at(pending.Xt, pending.Yt, pending.mu, pending.ln_mu));  // steps 5-8
}

void exact_table_contacts(Pressure pressure, std::span<const ContactInput> in, std::span<FrictionForces> out) {
  const bool wide = ExactTable::has_wide_sum();
  Block b;
  std::size_t lanes = 0;
  for (std::size_t j = 0; j < in.size(); ++j) {
    FrictionForces done;
    try {
      if (exact_table_begin(pressure, in[j], done, b.contact[lanes])) {
        out[j] = done;
        continue;
      }
    } catch (const std::exception& e) {
      // The contacts before it are all evaluated, those waiting in the block too, before it is
      // reported.
      const std::exception_ptr cause = std::current_exception();
      const std::string message = e.what();
      sum_block(b, lanes, wide, out);
      throw BatchError(j, cause, message);
    }
    const ExactTableContact& c = b.contact[lanes];
    b.cell[lanes] = c.table->locate(c.Xt, c.Yt, c.mu, c.ln_mu);  // steps 5-7
    b.index[lanes] = j;
    if (++lanes == kBlock) {
      sum_block(b, lanes, wide, out);
      lanes = 0;
    }
  }
  sum_block(b, lanes, wide, out);
}

}  // namespace frictionlab::friction
