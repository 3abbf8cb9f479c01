#pragma once
// Errors of bad input that name where the value came from and the rule it breaks, in one form:
//
//   KEY = VALUE is invalid: RULE        e.g. "body.mass = 1e-300 is invalid: it must be ..."
//
// KEY is what the user wrote (a scenario key "run.t_end", an option "--jobs", "friction input
// U"); VALUE is the value as the messages print numbers (number_format.h) or a quoted string.
// The exception keeps KEY, so that a caller can say who set it (a --set override, a file).

#include <span>
#include <stdexcept>
#include <string>
#include <string_view>

namespace frictionlab::support {

/// A std::invalid_argument that knows the key it is about.
class InvalidValue : public std::invalid_argument {
 public:
  /// what() = "KEY = VALUE_TEXT is invalid: RULE".
  InvalidValue(std::string_view key, std::string_view value_text, std::string_view rule);
  /// what() = MESSAGE, which must name the key (for rules that read better another way, e.g.
  /// "run.t_end is required").
  InvalidValue(std::string_view key, std::string message);

  [[nodiscard]] const std::string& key() const noexcept { return key_; }

 private:
  std::string key_;
};

/// "KEY = VALUE is invalid: RULE" with VALUE as a message number (number_format.h).
[[nodiscard]] InvalidValue invalid_value(std::string_view key, double value, std::string_view rule);
/// The same for an integer.
[[nodiscard]] InvalidValue invalid_value(std::string_view key, long long value, std::string_view rule);
/// The same with VALUE quoted: KEY = 'VALUE' is invalid: RULE.
[[nodiscard]] InvalidValue invalid_value(std::string_view key, std::string_view value, std::string_view rule);
/// The same for a vector: KEY = [x, y, z] is invalid: RULE.
[[nodiscard]] InvalidValue invalid_value(std::string_view key, std::span<const double> values, std::string_view rule);

/// One line: newlines and tabs become spaces, runs of blanks one blank, ends trimmed (for
/// messages from libraries that span several lines).
[[nodiscard]] std::string one_line(std::string_view message);

}  // namespace frictionlab::support
