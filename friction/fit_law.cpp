#include "friction/fit_law.h"

#include "friction/exact_law.h"
#include "friction/fit_batch.h"
#include "friction/standalone/fit_law.h"

namespace frictionlab::friction {
namespace {

frictionlab_fit::Pressure standalone_pressure(Pressure p) {
  switch (p) {
    case Pressure::hertz: return frictionlab_fit::Pressure::hertz;
    case Pressure::uniform: return frictionlab_fit::Pressure::uniform;
    case Pressure::punch: return frictionlab_fit::Pressure::punch;
  }
  return frictionlab_fit::Pressure::hertz;
}

}  // namespace

std::vector<LawParameter> FitLaw::parameters() { return ExactLaw::parameters(); }

double FitLaw::max_error() const { return frictionlab_fit::kMaxError[static_cast<int>(standalone_pressure(pressure_))]; }

// What holds by construction (friction/standalone/fit_law.h): the properties of `exact`, to the
// rounding of the closed form, for every axis ratio.
LawPromises FitLaw::promises() const {
  LawPromises p = ExactLaw(pressure_).promises();
  p.min_axis_ratio = 0.0;
  p.tolerance = kFitLawPromiseTolerance;
  return p;
}

FrictionForces FitLaw::do_evaluate(const ContactInput& in) const { return fit_contact(standalone_pressure(pressure_), in); }

// Several contacts at once across SIMD lanes, each bit for bit as do_evaluate (friction/fit_batch.h).
// fit rejects no valid contact: nothing to report.
void FitLaw::do_evaluate_batch(std::span<const ContactInput> in, std::span<FrictionForces> out) const {
  fit_contacts(standalone_pressure(pressure_), in, out);
}

}  // namespace frictionlab::friction
