#include "dynamics/shapes/shape_registry.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <shared_mutex>
#include <stdexcept>

#include "dynamics/shapes/profile.h"
#include "dynamics/shapes/body_of_revolution.h"
#include "dynamics/shapes/ellipsoid.h"
#include "dynamics/shapes/toroidal_disk.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::shapes {
namespace {

using support::InvalidValue;
using support::invalid_value;

struct Entry {
  ShapeRegistration registration;
  bool built_in = false;
};

bool valid_kind(std::string_view s) {
  if (s.empty() || s.front() == '-') return false;
  return std::all_of(s.begin(), s.end(), [](char c) { return (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-'; });
}

bool valid_parameter_name(std::string_view s) {
  if (s.empty() || (s.front() >= '0' && s.front() <= '9')) return false;
  return std::all_of(s.begin(), s.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
  });
}

std::string count_text(std::size_t count) {
  if (count == 0) return "one or more values";
  return count == 1 ? "one value" : std::to_string(count) + " values";
}

std::vector<Entry> built_ins() {
  std::vector<Entry> b;
  b.push_back({{"ellipsoid",
                "triaxial ellipsoid centred at the origin, semi-axes along the shape axes (closed form)",
                {{"semi_axes", 3, "m", "semi-axes a1, a2, a3 along e1, e2, e3, each > 0"}},
                [](const ShapeArguments& args) -> std::shared_ptr<const Shape> {
                  const auto& a = args.values("semi_axes");
                  return std::make_shared<const Ellipsoid>(Eigen::Vector3d(a[0], a[1], a[2]), args.key("semi_axes"));
                }},
               true});
  b.push_back({{"revolution",
                "convex body of revolution about e3, chi^2 a polynomial in the profile coordinate z (origin z = 0)",
                {{"chi2", 0, "m^(2-i)", "ascending coefficients of chi^2 in z (dynamics/shapes/profile.h's rules)"}},
                [](const ShapeArguments& args) -> std::shared_ptr<const Shape> {
                  return std::make_shared<const BodyOfRevolution>(Profile(args.values("chi2"), args.key("chi2")));
                }},
               true});
  b.push_back({{"toroidal-disk",
                "disk with a toroidal rim (flat faces at +-rim_radius, rim tube round the circle of radius radius), axis e3",
                {{"radius", 1, "m", "radius R of the circle the rim's tube runs round, > 0"},
                 {"rim_radius", 1, "m", "radius rho of the rim's tube (half the thickness), > 0"}},
                [](const ShapeArguments& args) -> std::shared_ptr<const Shape> {
                  return std::make_shared<const ToroidalDisk>(args.number("radius"), args.number("rim_radius"),
                                                              args.key("radius"), args.key("rim_radius"));
                }},
               true});
  return b;
}

class Registry {
 public:
  Registry() {
    for (auto& e : built_ins()) entries_.push_back(std::make_shared<const Entry>(std::move(e)));
  }

  void add(ShapeRegistration r) {
    if (!valid_kind(r.kind))
      throw std::invalid_argument("shape kind '" + r.kind + "' is not a valid name: use [a-z0-9][a-z0-9-]*");
    if (r.summary.empty()) throw std::invalid_argument("shape kind '" + r.kind + "' has no summary");
    if (!r.factory) throw std::invalid_argument("shape kind '" + r.kind + "' has no factory");
    for (std::size_t i = 0; i < r.parameters.size(); ++i) {
      const std::string& name = r.parameters[i].name;
      if (!valid_parameter_name(name) || name == "shape")
        throw std::invalid_argument("shape kind '" + r.kind + "': parameter name '" + name +
                                    "' is not valid: use [A-Za-z_][A-Za-z0-9_]*, not 'shape'");
      for (std::size_t j = 0; j < i; ++j)
        if (r.parameters[j].name == name)
          throw std::invalid_argument("shape kind '" + r.kind + "': parameter '" + name + "' is declared twice");
    }
    const std::unique_lock lock(mutex_);
    if (find_locked(r.kind))
      throw std::invalid_argument("shape kind '" + r.kind + "' is already registered: choose another name");
    entries_.push_back(std::make_shared<const Entry>(Entry{std::move(r), false}));
  }

  bool remove(std::string_view kind) {
    const std::unique_lock lock(mutex_);
    const auto it = std::find_if(entries_.begin(), entries_.end(),
                                 [&](const auto& e) { return e->registration.kind == kind; });
    if (it == entries_.end()) return false;
    if ((*it)->built_in)
      throw std::invalid_argument("shape kind '" + std::string(kind) +
                                  "' is built-in: only kinds added by register_shape() can be unregistered");
    entries_.erase(it);
    return true;
  }

  std::vector<std::shared_ptr<const Entry>> all() const {
    const std::shared_lock lock(mutex_);
    return entries_;
  }

  std::shared_ptr<const Entry> find(std::string_view kind) const {
    const std::shared_lock lock(mutex_);
    return find_locked(kind);
  }

 private:
  std::shared_ptr<const Entry> find_locked(std::string_view kind) const {
    for (const auto& e : entries_)
      if (e->registration.kind == kind) return e;
    return nullptr;
  }

  mutable std::shared_mutex mutex_;
  std::vector<std::shared_ptr<const Entry>> entries_;
};

Registry& registry() {
  static Registry r;
  return r;
}

std::string join_kinds() {
  std::string s;
  for (const auto& k : shape_kinds()) s += (s.empty() ? "" : ", ") + k;
  return s;
}

// Checks the spec's parameters against the declaration: each given one declared, each declared
// one given with its count, every value finite.
void check_parameters(const ShapeSpec& spec, const ShapeRegistration& r) {
  const ShapeArguments args(spec);
  std::string names;
  for (const auto& p : r.parameters) names += (names.empty() ? "" : ", ") + p.name;
  for (const auto& [name, values] : spec.parameters) {
    const bool declared =
        std::any_of(r.parameters.begin(), r.parameters.end(), [&](const auto& p) { return p.name == name; });
    if (!declared)
      throw InvalidValue(args.key(name), args.key(name) + " is not a parameter of the '" + r.kind + "' shape; " +
                                             (names.empty() ? "it takes none" : "its parameters: " + names));
  }
  for (const auto& p : r.parameters) {
    const std::string key = args.key(p.name);
    const std::string what = p.doc + " (" + count_text(p.count) + ", " + p.unit + ")";
    const auto it = spec.parameters.find(p.name);
    if (it == spec.parameters.end())
      throw InvalidValue(key, key + " is required by the '" + r.kind + "' shape: " + what);
    const auto& v = it->second;
    if (p.count == 0 ? v.empty() : v.size() != p.count)
      throw invalid_value(key, v, "the '" + r.kind + "' shape needs " + what);
    if (!std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); }))
      throw invalid_value(key, v, "every value must be finite");
  }
}

}  // namespace

const std::vector<double>& ShapeArguments::values(const std::string& name) const {
  const auto it = spec_.parameters.find(name);
  if (it == spec_.parameters.end())  // a factory asking for what it did not declare
    throw std::logic_error("shape factory asked for the undeclared parameter '" + name + "'");
  return it->second;
}

std::string ShapeArguments::key(std::string_view name) const {
  std::string k = spec_.section;
  if (!k.empty()) k += '.';
  return k.append(name);
}

std::vector<std::string> shape_kinds() {
  std::vector<std::string> k;
  for (const auto& e : registry().all()) k.push_back(e->registration.kind);
  return k;
}

std::vector<ShapeInfo> list_shapes() {
  std::vector<ShapeInfo> out;
  for (const auto& e : registry().all())
    out.push_back({e->registration.kind, e->registration.summary, e->registration.parameters});
  return out;
}

std::shared_ptr<const Shape> make_shape(const ShapeSpec& spec) {
  const ShapeArguments args(spec);
  const auto entry = registry().find(spec.kind);
  if (!entry)
    throw invalid_value(args.key("shape"), spec.kind, "it is not a known shape; known shapes: " + join_kinds());
  check_parameters(spec, entry->registration);
  auto shape = entry->registration.factory(args);
  if (!shape || shape->kind() != spec.kind)
    throw std::logic_error("the factory of shape kind '" + spec.kind + "' made " +
                           (shape ? "a shape of kind '" + std::string(shape->kind()) + "'" : std::string("nothing")));
  return shape;
}

void register_shape(ShapeRegistration registration) { registry().add(std::move(registration)); }

bool unregister_shape(std::string_view kind) { return registry().remove(kind); }

}  // namespace frictionlab::dynamics::shapes
