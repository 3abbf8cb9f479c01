#include "friction/exact_table_law.h"

#include "friction/exact_law.h"
#include "friction/exact_table.h"
#include "friction/exact_table_batch.h"

namespace frictionlab::friction {

std::vector<LawParameter> ExactTableLaw::parameters() { return ExactLaw::parameters(); }

// Every property of the exact law (it is the exact law, tabulated), to the table's accuracy and on
// its range of axis ratios.
LawPromises ExactTableLaw::promises() const {
  LawPromises p = ExactLaw(pressure_).promises();
  p.min_axis_ratio = kExactTableMinAxisRatio;
  p.tolerance = kExactTableAccuracy;
  return p;
}

// The steps of docs/exact-table.md, "Evaluation, in order" (friction/exact_table_batch.cpp, with the
// batch that shares them).
FrictionForces ExactTableLaw::do_evaluate(const ContactInput& in) const { return exact_table_contact(pressure_, in); }

// Blocks of contacts, their table rows fetched together and their weights across SIMD lanes, each
// bit for bit as do_evaluate (friction/exact_table_batch.h).
void ExactTableLaw::do_evaluate_batch(std::span<const ContactInput> in, std::span<FrictionForces> out) const {
  exact_table_contacts(pressure_, in, out);
}

}  // namespace frictionlab::friction
