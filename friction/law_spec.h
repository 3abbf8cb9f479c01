#pragma once
// Law specs: a friction law named together with its parameters, e.g. `exact:pressure=uniform`.
// docs/extending.md states the grammar and the rules with examples; in short:
//
//   spec  := NAME | NAME ":" KEY "=" VALUE { "," KEY "=" VALUE }
//   list  := spec { SEP spec },  SEP := ";"  or  a "," whose next item is not KEY=VALUE
//   NAME  := [A-Za-z0-9][A-Za-z0-9._+-]*          (a registered law)
//   KEY   := [A-Za-z_][A-Za-z0-9_]*               (a parameter the law declares; case matters)
//   VALUE := one or more characters other than , ; : = and white space
//
// so `exact,exact:pressure=uniform,pade-printed` is three laws, and `ellipsoidal:Rb=0.01,x=2;exact`
// or `ellipsoidal:Rb=0.01,x=2,exact` two: an item of a comma list that reads KEY=VALUE belongs to
// the spec before it. Specs contain no white space; items of a list may be padded with spaces.
//
// Each law declares its parameters (LawParameter): a choice among named values or a number in a
// range, with its default, unit and a one-line description. bind_law_spec() checks a parsed spec
// against them and gives the factory the values (LawArguments). Every error is
// std::invalid_argument naming the spec, the key, the value and the rule, and listing what is
// allowed.

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace frictionlab::friction {

/// One parameter a law declares.
struct LawParameter {
  enum class Kind { choice, number };

  std::string key;                  ///< KEY in the spec, e.g. "pressure", "Rb"
  Kind kind = Kind::choice;
  std::vector<std::string> choices;  ///< choice: the allowed values
  double min = 0.0;                  ///< number: the allowed range, its ends open or closed
  double max = 0.0;
  bool min_open = false;
  bool max_open = false;
  std::string unit;           ///< number: SI unit ("m"), empty if dimensionless
  std::string default_value;  ///< the value used when the spec omits the key, as text; empty:
                              ///< no default (the law then does what default_doc says)
  std::string default_doc;    ///< no default: what the law does without the key (one phrase)
  std::string doc;            ///< one line: what the parameter means

  /// A choice among `choices` (at least one), `default_value` one of them.
  [[nodiscard]] static LawParameter choice(std::string key, std::vector<std::string> choices,
                                           std::string default_value, std::string doc);
  /// A finite number in [min, max] (ends open if so flagged; +-inf for no bound) in `unit`, with
  /// a default inside the range, or none: then `default_doc` says what the law does without it.
  [[nodiscard]] static LawParameter number(std::string key, double min, bool min_open, double max,
                                           bool max_open, std::string unit,
                                           std::optional<double> default_value,
                                           std::string default_doc, std::string doc);

  /// The rule a value must satisfy, e.g. "one of hertz, uniform, punch" or
  /// "a finite number in (0, inf) m".
  [[nodiscard]] std::string rule() const;
  /// One line for `frictionlab laws`: "pressure = hertz|uniform|punch (default hertz): ...".
  [[nodiscard]] std::string describe() const;
};

/// A spec split into its name and its KEY=VALUE pairs (in the order given), syntax only.
struct ParsedLawSpec {
  std::string text;  ///< the spec as given
  std::string name;
  std::vector<std::pair<std::string, std::string>> arguments;
};

/// Parses NAME[:KEY=VALUE[,KEY=VALUE]...]; std::invalid_argument naming the spec and what is wrong
/// (empty, white space, a bad name or key, a missing value, an empty parameter list).
[[nodiscard]] ParsedLawSpec parse_law_spec(std::string_view spec);

/// Splits a list of specs by the grammar above (items trimmed of spaces); std::invalid_argument on
/// an empty list or item, or a list that starts with KEY=VALUE.
[[nodiscard]] std::vector<std::string> split_law_list(std::string_view list);

/// Checks a law's name and parameter declarations (std::invalid_argument naming what is wrong):
/// the name and keys follow the grammar, keys are unique, choices non-empty and well-formed,
/// ranges ordered, defaults allowed by their own rule.
void check_law_declaration(std::string_view name, const std::vector<LawParameter>& parameters);

/// The parameters of one law, as a spec sets them (validated; defaults filled in).
class LawArguments {
 public:
  /// No spec: the law `name` with every parameter at its default.
  LawArguments(std::string name, std::vector<LawParameter> parameters);

  /// The spec as given (verbatim), or the name if none was.
  [[nodiscard]] const std::string& spec() const { return spec_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  /// The same law written canonically: the name, then the parameters that differ from their
  /// default in declaration order, numbers in shortest round-trip form. Two specs denote the same
  /// law iff their canonical forms are equal ("exact:pressure=hertz" is "exact").
  [[nodiscard]] std::string canonical() const;

  /// The value of the choice parameter `key` (given, or its default). std::logic_error if the
  /// law declares no choice parameter `key` (a bug in the law's factory, not bad input).
  [[nodiscard]] const std::string& choice(std::string_view key) const;
  /// The value of the number parameter `key` (given, or its default), or nullopt if it has none.
  /// std::logic_error if the law declares no number parameter `key`.
  [[nodiscard]] std::optional<double> number(std::string_view key) const;
  /// True if the spec sets `key` (even to its default value).
  [[nodiscard]] bool given(std::string_view key) const;

 private:
  friend LawArguments bind_law_spec(const ParsedLawSpec& spec, const std::vector<LawParameter>& parameters);
  struct Value {
    LawParameter parameter;
    bool given = false;
    bool has_value = false;
    std::string text;  // the choice, or the number as given
    double number = 0.0;
  };
  [[nodiscard]] const Value& find(std::string_view key, LawParameter::Kind kind) const;

  std::string spec_;
  std::string name_;
  std::vector<Value> values_;  // one per declared parameter, in declaration order
};

/// Checks `spec`'s arguments against the law's declared `parameters` (the name is not looked up
/// here): std::invalid_argument on an unknown key (listing the law's keys), a key given twice, or
/// a value its rule does not allow (naming the value and the rule).
[[nodiscard]] LawArguments bind_law_spec(const ParsedLawSpec& spec, const std::vector<LawParameter>& parameters);

/// A file-name stem for `spec` ("exact:pressure=uniform" -> "exact_pressure-uniform": ':' and ','
/// become '_', '=' becomes '-', ';' and anything else outside [A-Za-z0-9._+-] becomes '_'): safe
/// in paths, in relative links of markdown (where "a:b" would read as a URL scheme) and in gnuplot.
[[nodiscard]] std::string law_file_stem(std::string_view spec);

}  // namespace frictionlab::friction
