#pragma once
// A simulation scenario: a TOML file with sections [body], [contact], [initial], [run]
// (docs/dynamics.md §7 lists every key, its unit, default and rule). Unknown keys, wrong types
// and bad values are std::invalid_argument naming the key ("run.t_end", ...). Overrides
// "key=value" (the command line's --set) use the same key paths and are applied before checking;
// a value is read as TOML ("2", "1e-3", "[0, 0, 1]", "\"exact\"") or else taken as a bare string.
//
// A scenario, once resolved (file + overrides + law), is the one source of truth of a run: it
// carries its built body and its law, and its `resolved_toml`, written beside the run as
// scenario.toml, reads back as the same scenario (every number to the last bit), so that
// rerunning it reproduces the run.

#include <Eigen/Core>
#include <filesystem>
#include <memory>
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
  std::string name;         ///< top-level `name`, or the stem of the file first read
  std::string description;  ///< top-level `description`
  std::string source;       ///< the file read (or the name given to parse_scenario)
  std::vector<std::string> overrides;  ///< the "key=value" overrides applied, in order
  BodySpec body_spec;       ///< [body] as written
  Body body;                ///< built from body_spec once, when the scenario was resolved
  PlaneContact contact;
  std::string law;          ///< [contact] law: a registry name (friction/registry.h), checked
  InitialState initial;
  RunOptions run;
  /// The scenario after overrides as TOML, with its name and law written out: what scenario.toml
  /// beside a run contains.
  std::string resolved_toml;
};

/// The physically meaningful ranges of scenario values, checked when a scenario is resolved
/// (docs/dynamics.md §7 gives each rule with its key). Beyond them the model of a rigid body on a
/// Hertz plane does not hold, and products the integration forms (m g, lambda |eps|^1.5,
/// omega^2 J, k N) would leave the range of doubles long before: a value outside is an error
/// naming its key, not a failure far downstream.
struct ScenarioLimits {
  static constexpr double kMinMass = 1e-6;  ///< kg: a grain of 1 mg
  static constexpr double kMaxMass = 1e6;   ///< kg: 1000 tonnes
  /// m: the body's length along its axis and its largest diameter (10 µm to 1 km).
  static constexpr double kMinSize = 1e-5;
  static constexpr double kMaxSize = 1e3;
  /// A >= this * m r_max^2 and C >= this * m rho_max^2 (r_max: the farthest surface point from the
  /// centre of mass, rho_max: the largest radius). Every body has A <= m r_max^2 and
  /// C <= m rho_max^2 (its mass lies inside it); far below, its rotation would be ~1/sqrt(this)
  /// faster than its size suggests.
  static constexpr double kMinInertiaFraction = 1e-6;
  static constexpr double kMaxFriction = 10.0;  ///< contact.k: measured dry friction stays below ~4
  static constexpr double kMinStiffness = 1e-3;  ///< N/m^1.5: softer than any gel of micrometre size
  static constexpr double kMaxStiffness = 1e15;  ///< N/m^1.5: stiffer than diamond at 1 km radius
  static constexpr double kMaxGravity = 1e3;     ///< m/s^2, ~100 g
  /// The static compression (m g / lambda)^(2/3) and a starting penetration -eps stay below this
  /// fraction of the body's smallest size: Hertz's law is one of small compressions.
  static constexpr double kMaxCompressionFraction = 0.05;
  static constexpr double kMaxHeight = 1e3;  ///< m: the highest start above the plane (initial.eps)
  /// m/s: the largest speed of the centre of mass (initial.v) and of a surface point about it
  /// (|omega| r_max): a rifle bullet's; faster impacts are not elastic.
  static constexpr double kMaxSpeed = 1e3;
};

/// |gamma| may differ from 1 by at most this before normalisation (a typed-in unit vector with
/// ~4 digits passes; a wrong vector does not).
inline constexpr double kGammaUnitTolerance = 1e-3;

/// A scenario file read and parsed once. Each resolve() applies its overrides to a copy of the
/// parsed text, checks every key and builds the body: one document serves many runs.
class ScenarioDocument {
 public:
  /// Reads and parses a file; errors name it (and line:column for TOML syntax).
  [[nodiscard]] static ScenarioDocument read(const std::filesystem::path& file);
  /// Parses TOML text; `source` names it in messages and gives the default scenario name.
  [[nodiscard]] static ScenarioDocument parse(std::string_view toml_text, const std::string& source);

  /// The scenario with `overrides` applied, checked, its body built.
  [[nodiscard]] Scenario resolve(const std::vector<std::string>& overrides = {}) const;
  [[nodiscard]] const std::string& source() const { return source_; }

 private:
  struct Parsed;
  ScenarioDocument(std::shared_ptr<const Parsed> parsed, std::string source);
  std::shared_ptr<const Parsed> parsed_;
  std::string source_;
};

/// ScenarioDocument::read(file).resolve(overrides).
[[nodiscard]] Scenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides = {});
/// ScenarioDocument::parse(toml_text, source).resolve(overrides).
[[nodiscard]] Scenario parse_scenario(std::string_view toml_text, const std::string& source,
                                      const std::vector<std::string>& overrides = {});

/// The state at t = 0 (zero accumulated work).
[[nodiscard]] StateVector initial_state(const Scenario& s);

}  // namespace frictionlab::dynamics
