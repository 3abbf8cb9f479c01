#pragma once
// A simulation scenario: a TOML file with sections [body], [contact], [initial], [run]
// (docs/dynamics.md §7 lists every key, its unit, default and rule). Unknown keys, wrong types
// and bad values are std::invalid_argument naming the key ("run.t_end", ...). Overrides
// "key=value" (the command line's --set) use the same key paths and are applied before checking;
// a value is read as TOML ("2", "1e-3", "[0, 0, 1]", "\"exact\"") or else taken as a bare string.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "dynamics/body.h"
#include "dynamics/hertz_contact.h"
#include "dynamics/simulation.h"
#include "dynamics/state.h"

namespace frictionlab::dynamics {

/// [initial]: vectors in the body frame.
struct InitialState {
  Eigen::Vector3d gamma = Eigen::Vector3d::UnitZ();  ///< upward vertical; normalised on reading
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();   ///< angular velocity, 1/s
  Eigen::Vector3d v = Eigen::Vector3d::Zero();       ///< velocity of the centre of mass, m/s
  double eps = 0.0;                                  ///< contact height, m ("static": -(mg/lambda)^(2/3))
};

struct Scenario {
  std::string name;         ///< top-level `name`, or the file stem
  std::string description;  ///< top-level `description`
  std::string source;       ///< the file read (or the name given to parse_scenario)
  std::vector<std::string> overrides;  ///< the "key=value" overrides applied, in order
  BodySpec body;
  PlaneContact contact;
  std::string law = "exact";  ///< [contact] law: a registry name (friction/registry.h)
  InitialState initial;
  RunOptions run;
  std::string resolved_toml;  ///< the scenario after overrides, as TOML (written beside the output)
};

/// |gamma| may differ from 1 by at most this before normalisation (a typed-in unit vector with
/// ~4 digits passes; a wrong vector does not).
inline constexpr double kGammaUnitTolerance = 1e-3;

/// Reads and checks a scenario file (and its overrides). The body is built once to check it.
[[nodiscard]] Scenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
/// The same from TOML text; `source` names it in messages.
[[nodiscard]] Scenario parse_scenario(std::string_view toml_text, const std::string& source,
                                      const std::vector<std::string>& overrides = {});

/// The state at t = 0 (zero accumulated work).
[[nodiscard]] StateVector initial_state(const Scenario& s);

}  // namespace frictionlab::dynamics
