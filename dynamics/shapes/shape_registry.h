#pragma once
// Shapes by kind: a scenario names a shape family and its parameters (a ShapeSpec, which the
// scenario reader fills from the [body] section), and make_shape() builds it, checking the
// parameters against the kind's declaration; errors name the scenario key (`body.semi_axes`) and
// the rule. The built-in kinds are registered here; user code adds its own with register_shape()
// (no edit of this file): docs/convex-bodies.md §7 has a complete example, compiled as a test.
//
// Built-in kinds and their parameters (SI units):
//   ellipsoid       semi_axes = [a1, a2, a3]   m, > 0: semi-axes along e1, e2, e3 (dynamics/shapes/ellipsoid.h)
//   revolution      chi2 = [c0, c1, ...]       ascending coefficients of chi^2 in z, m^(2-i)
//                                              (dynamics/shapes/profile.h's rules; dynamics/shapes/body_of_revolution.h)
//   toroidal-disk   radius = R, rim_radius = rho   m, > 0 (dynamics/shapes/toroidal_disk.h)

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dynamics/shapes/shape.h"

namespace frictionlab::dynamics::shapes {

/// What a scenario says about the shape.
struct ShapeSpec {
  std::string kind;                                      ///< a registered kind (shape_kinds())
  std::map<std::string, std::vector<double>> parameters; ///< parameter name -> its values (one for a number)
  /// The scenario section the keys belong to: errors name "<section>.<parameter>" and
  /// "<section>.shape" for the kind.
  std::string section = "body";
};

/// One parameter a kind takes.
struct ShapeParameter {
  std::string name;       ///< e.g. "semi_axes": [A-Za-z_][A-Za-z0-9_]*
  std::size_t count = 1;  ///< how many values; 0: one or more
  std::string unit;       ///< of each value, e.g. "m"
  std::string doc;        ///< one line: what the values are, e.g. "semi-axes a1, a2, a3 along e1, e2, e3"
};

/// The validated parameters handed to a factory.
class ShapeArguments {
 public:
  /// Made by make_shape() for the factory.
  explicit ShapeArguments(const ShapeSpec& spec) : spec_(spec) {}
  /// The values of a declared parameter (present, with the declared count, all finite).
  [[nodiscard]] const std::vector<double>& values(const std::string& name) const;
  /// The single value of a declared one-value parameter.
  [[nodiscard]] double number(const std::string& name) const { return values(name).front(); }
  /// The scenario key of a parameter, "<section>.<name>", for error messages.
  [[nodiscard]] std::string key(std::string_view name) const;

 private:
  const ShapeSpec& spec_;
};

/// Makes the shape from validated arguments; throws std::invalid_argument naming args.key(...) for
/// values its rules reject (e.g. a negative semi-axis).
using ShapeFactory = std::function<std::shared_ptr<const Shape>(const ShapeArguments&)>;

/// Everything the registry knows of a kind.
struct ShapeRegistration {
  std::string kind;                        ///< [a-z0-9][a-z0-9-]*, not yet taken; Shape::kind() of what it makes
  std::string summary;                     ///< one line
  std::vector<ShapeParameter> parameters;  ///< each required
  ShapeFactory factory;
};

/// A registered kind, as listings show it.
struct ShapeInfo {
  std::string kind;
  std::string summary;
  std::vector<ShapeParameter> parameters;
};

/// The registered kinds: the built-in ones first (ellipsoid, revolution, toroidal-disk), then the
/// user's in the order registered.
[[nodiscard]] std::vector<std::string> shape_kinds();
/// The same, with summaries and parameters.
[[nodiscard]] std::vector<ShapeInfo> list_shapes();

/// Builds the shape `spec` describes. std::invalid_argument (support::InvalidValue, keyed) naming
/// the key and the rule for an unknown kind (listing the known ones), a parameter the kind does not
/// take (listing its parameters), a missing parameter, a wrong number of values, a value that is not
/// finite, or a value the shape's own rules reject. The factory must make a shape of the kind asked.
[[nodiscard]] std::shared_ptr<const Shape> make_shape(const ShapeSpec& spec);

/// Adds a kind, known from then on to make_shape() and the listings. Thread-safe.
/// std::invalid_argument if the kind is taken or malformed, a parameter name is malformed or
/// repeated, the summary is empty or there is no factory.
void register_shape(ShapeRegistration registration);

/// Registers a kind when constructed (a namespace-scope `const ShapeRegistrar` in the user's own
/// source file, linked into the program, registers before main() runs).
struct ShapeRegistrar {
  explicit ShapeRegistrar(ShapeRegistration registration) { register_shape(std::move(registration)); }
};

/// Removes a kind added by register_shape() (shapes already made stay valid). Returns false if no
/// such kind was registered; std::invalid_argument for a built-in kind. Thread-safe.
bool unregister_shape(std::string_view kind);

}  // namespace frictionlab::dynamics::shapes
