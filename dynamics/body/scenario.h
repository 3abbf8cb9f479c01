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

#include "dynamics/body/body.h"
#include "dynamics/contact/hertz_contact.h"
#include "dynamics/body/simulation.h"
#include "dynamics/body/state.h"

namespace frictionlab::dynamics {

/// [initial]: vectors in the body frame.
struct InitialState {
  Eigen::Vector3d gamma = Eigen::Vector3d::UnitZ();  ///< upward vertical; normalised on reading
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();   ///< angular velocity, 1/s
  Eigen::Vector3d v = Eigen::Vector3d::Zero();       ///< velocity of the centre of mass, m/s
  double eps = 0.0;                                  ///< contact height, m ("static": -(mg/lambda)^(2/3))
  /// The pose at t = 0 (not fed back, dynamics/body/state.h): the centre of mass on the plane (m,
  /// world axes) and the heading (rad): the body is tilted so that gamma is up by the shortest
  /// turn, then turned by `heading` about the vertical.
  Eigen::Vector2d position = Eigen::Vector2d::Zero();
  double heading = 0.0;
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

  /// The scenario with `overrides` applied, checked, its body built. A file of another model
  /// (`model = "puck"`) is an error naming the key `model`.
  [[nodiscard]] Scenario resolve(const std::vector<std::string>& overrides = {}) const;
  [[nodiscard]] const std::string& source() const { return source_; }

  /// The top-level `model` after `overrides`: "body" (a body of revolution on a Hertz plane, also
  /// when absent) or "puck" (dynamics/puck/). Another value is std::invalid_argument naming it.
  [[nodiscard]] std::string model(const std::vector<std::string>& overrides = {}) const;

  /// The parsed text (complete in dynamics/io/scenario_toml.h, for the models' own readers).
  struct Parsed;
  [[nodiscard]] const Parsed& parsed() const { return *parsed_; }

 private:
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
