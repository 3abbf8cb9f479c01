#pragma once
// Reading scenario files (TOML), shared by every model's reader (the body of revolution,
// dynamics/body/scenario.h; the puck, dynamics/puck/): typed reads of a section that remember which
// keys were used and reject the others, "--set key=value" overrides, the [run] section, and the
// rule that an error is blamed on the --set that set its key or else on the file.
// Internal to the scenario readers: it exposes toml++ (a private dependency).

#include <toml++/toml.h>

#include <Eigen/Core>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "dynamics/body/scenario.h"
#include "dynamics/core/run_options.h"

namespace frictionlab::dynamics {

/// The parsed text of a scenario file (dynamics/body/scenario.h).
struct ScenarioDocument::Parsed {
  toml::table root;
};

namespace scenario_toml {

/// Throws std::invalid_argument(msg).
[[noreturn]] void fail(const std::string& msg);
/// An error about one key (so that the caller can tell whether an override set it).
[[noreturn]] void fail_at(const std::string& key, const std::string& msg);

/// "a string", "a number", ... (for messages).
[[nodiscard]] std::string type_name(const toml::node& n);
/// The value as written, shortened to 60 characters (for messages).
[[nodiscard]] std::string shown(const toml::node& n);

/// One section of the file: typed reads that remember which keys were used, then a check that no
/// other key is present.
class Section {
 public:
  Section(const toml::table* t, std::string name) : t_(t), name_(std::move(name)) {}

  [[nodiscard]] bool has(const std::string& key);
  [[nodiscard]] std::string path(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }

  const toml::node& node(const std::string& key);
  double number(const std::string& key);
  double number(const std::string& key, double fallback);
  std::optional<double> optional_number(const std::string& key);
  long integer(const std::string& key, long fallback);
  std::string string(const std::string& key, const std::string& fallback);
  bool boolean(const std::string& key, bool fallback);
  std::vector<double> numbers(const std::string& key);
  /// An array of strings, or one string (a list of one); absent: empty.
  std::vector<std::string> strings(const std::string& key);
  Eigen::Vector3d vector3(const std::string& key);
  Eigen::Vector3d vector3(const std::string& key, const Eigen::Vector3d& fallback);
  /// A vector of exactly `n` numbers.
  std::vector<double> numbers(const std::string& key, std::size_t n);

  /// Throws (naming the key and the known keys) if the section has a key that was never read.
  void check_no_unknown_keys(const std::vector<std::string>& allowed_hint) const;

  static double as_number(const toml::node& n, const std::string& where);

 private:
  const toml::table* t_;
  std::string name_;
  std::set<std::string> used_;
};

/// The section `name` of `root`, or nullptr if absent and not required.
[[nodiscard]] const toml::table* section_table(const toml::table& root, const std::string& name, bool required);

/// Applies "key=value" to `root` (the value read as TOML, else taken as a bare string).
void apply_override(toml::table& root, const std::string& assignment);

/// Who set the value an error is about: "--set KEY=VALUE" (the last override of its key) or `source`.
[[nodiscard]] std::string blamed(const std::invalid_argument& e, const std::vector<std::string>& overrides,
                                 const std::string& source);

/// Which [run] keys a model has.
enum class RunKeys {
  body,  ///< every key of docs/dynamics.md §7
  puck   ///< no contact settling, rolling, stagnation or kinetic-energy threshold (a rigid plane)
};

/// Reads [run] (required) into RunOptions and validates it; unknown keys are errors.
[[nodiscard]] RunOptions read_run(const toml::table& root, RunKeys keys);

/// The top-level `model` of `root`: "body" (also when absent) or "puck"; any other value is an error.
[[nodiscard]] std::string model_of(const toml::table& root);

/// The friction law spec (friction::make_law accepts it), or an error naming `key`.
void check_law_spec(const std::string& key, const std::string& spec);

}  // namespace scenario_toml
}  // namespace frictionlab::dynamics
