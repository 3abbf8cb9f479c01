#include "friction/fit_law.h"

#include "friction/exact_law.h"
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

FrictionForces FitLaw::do_evaluate(const ContactInput& in) const {
  const PatchAngle::CosSin axis = in.psi.cos_sin();
  const frictionlab_fit::Geometry g = frictionlab_fit::make_geometry(in.b / in.a, standalone_pressure(pressure_));
  const frictionlab_fit::Forces f = frictionlab_fit::evaluate(g, in.U, in.Omega, in.a, axis.c, axis.s, in.N, in.k);
  return {f.F1, f.F2, f.M};
}

}  // namespace frictionlab::friction
