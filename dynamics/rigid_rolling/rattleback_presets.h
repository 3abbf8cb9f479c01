#pragma once
// Published rattleback parameter sets for the rigid rolling reference (docs/rigid-rolling.md §2.3).
//
// kane_levinson_rattleback(): T. R. Kane and D. A. Levinson, "Realistic mathematical modeling of the
// rattleback", Int. J. Non-Linear Mech. 17 (1982) 175-186. Semi-axes 20, 3, 2 cm; the centre of
// mass 1 cm from the ellipsoid's centre towards the contact point; per unit mass, moments 2, 16,
// 17 cm^2 about the long, intermediate and vertical axes and an off-diagonal term of magnitude
// 0.2 cm^2 in the horizontal plane; here m = 1 kg and g = 9.81 m/s^2 (as in the Autolev sample
// problem of the same body). Sign: in Kane and Levinson's equations the term D enters the inertia
// matrix where the tensor element does (I12 = D - M x1 x2, their eqs. 58-63 as transcribed in
// pydy's examples/rattleback/cpp/reproduceKane1982.cc), in a frame whose third axis points towards
// the contact point, with D = -0.2 cm^2 per unit mass (two independent transcriptions; the Autolev
// sample, third axis up, lists the product of inertia 0.2 kg cm^2). Turned to this project's frame
// (x long, y intermediate, z up: a half turn about x), the tensor element is J12 = +0.2e-4 kg m^2
// (the integral of x y dm is -0.2e-4 kg m^2): the principal axis of least inertia is turned 0.82
// degrees clockwise (seen from above) from the long axis, misalignment_angle = -0.0143 rad. With
// that, spin counter-clockwise seen from above (omega . gamma > 0) is the fast-unstable sense (the
// pitch mode grows, 10x faster than the roll mode does for the other sense at slow spin).

#include "dynamics/rigid_rolling/ellipsoid_body.h"

namespace frictionlab::dynamics::rigid_rolling {

/// Kane & Levinson (1982), SI units, m = 1 kg (see the header comment for the sign of J12).
[[nodiscard]] EllipsoidBody kane_levinson_rattleback();

}  // namespace frictionlab::dynamics::rigid_rolling
