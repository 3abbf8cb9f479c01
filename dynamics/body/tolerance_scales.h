#pragma once
// Per-component scales of the integrator's absolute tolerance: component i of the state may carry
// a local error of run.abs_tol * scale_i (+ run.rel_tol |x_i|), GSL's scaled error control
// (gsl_odeiv2_control_scaled_new). One absolute tolerance for every component would mix units: 1e-9
// is loose for eps (about 1e-5 of the egg's static compression, i.e. 1.5e-5 of its weight in N)
// and tight for omega (1e-11 of 100 1/s). The scales (dynamics/body/body_scales.h) are the magnitudes a
// component takes in a motion of the body over its own size:
//   v (m/s)      sqrt(g R)         omega (1/s)  sqrt(g/R)        gamma  1
//   eps (m)      |eps_s|, the static Hertz compression (so the error in N = lambda |eps|^1.5
//                is about 1.5 abs_tol of the weight)
//   W_slide, W_spin (J)  m g R
//   position, orientation  infinite: the pose is carried beside the state, not fed back
//                (dynamics/body/state.h), and does not take part in the error control

#include "dynamics/body/body_scales.h"
#include "dynamics/body/state.h"

namespace frictionlab::dynamics {

[[nodiscard]] StateVector absolute_tolerance_scales(const BodyScales& scales);

}  // namespace frictionlab::dynamics
