#pragma once
// The physics engines' spin-friction laws as the calibration study sees them: each has one length
// coefficient, written here dimensionless as c (docs/engines.md §2).
//
//   ellipsoidal:Rb=...           Rb        = c a       (M at pure spin: kN Rb)
//   mujoco-elliptic:torsional=...torsional = c k a     (M at pure spin: N torsional)
//   decoupled:r_spin=...         r_spin    = c k a     (M at pure spin: N r_spin)
//
// so that, for every law, c is the pure-spin torque per kNa: c = 3 pi/16 makes each of them exact at
// pure spin on a circular Hertz patch of radius a. The factor k of the last two is a fact of the
// laws (MuJoCo's and the engines' torque limits are per unit normal force, not per kN).

#include <memory>
#include <string>
#include <vector>

#include "friction/law.h"

namespace frictionlab::calibration {

/// One engine law with its single length parameter.
struct EngineLaw {
  std::string name;         ///< registry name, e.g. "mujoco-elliptic"
  std::string key;          ///< the parameter of its spec, e.g. "torsional" (a length, m)
  bool per_unit_load = false;  ///< the parameter is c k a (a torque per N) rather than c a (per kN)
  std::string engines;      ///< where the law is used, for tables: "MuJoCo (condim 4, elliptic cone)"
};

/// The engine laws the study calibrates, in table order.
[[nodiscard]] const std::vector<EngineLaw>& engine_laws();

/// The engine law called `name`; std::invalid_argument listing the known names otherwise.
[[nodiscard]] const EngineLaw& engine_law(const std::string& name);

/// The parameter value (m) for the dimensionless coefficient c on a patch of major semi-axis a (m)
/// with friction coefficient k: c a, or c k a for a per-unit-load parameter.
[[nodiscard]] double parameter_value(const EngineLaw& law, double c, double a, double k);

/// The law's spec with its parameter set for c, a, k, e.g. "decoupled:r_spin=0.0123" (shortest
/// round-trip number).
[[nodiscard]] std::string engine_spec(const EngineLaw& law, double c, double a, double k);

/// The law `engine_spec(law, c, a, k)` denotes, made by the registry (its spec() is that spec).
[[nodiscard]] std::unique_ptr<friction::FrictionLaw> make_engine_law(const EngineLaw& law, double c, double a,
                                                                     double k);

}  // namespace frictionlab::calibration
