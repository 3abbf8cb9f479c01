#include "dynamics/scenario.h"

#include <toml++/toml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace frictionlab::dynamics {
namespace {

[[noreturn]] void fail(const std::string& msg) { throw std::invalid_argument(msg); }

std::string type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a number";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    default: return "a date/time";
  }
}

std::string shown(const toml::node& n) {
  std::ostringstream s;
  n.visit([&](const auto& v) { s << v; });
  std::string out = s.str();
  if (out.size() > 60) out = out.substr(0, 57) + "...";
  return out;
}

// One section of the file: typed reads that remember which keys were used, then a check that no
// other key is present.
class Section {
 public:
  Section(const toml::table* t, std::string name) : t_(t), name_(std::move(name)) {}

  [[nodiscard]] bool has(const std::string& key) {
    used_.insert(key);
    return t_ && t_->contains(key);
  }
  [[nodiscard]] std::string path(const std::string& key) const { return name_.empty() ? key : name_ + "." + key; }

  const toml::node& node(const std::string& key) {
    used_.insert(key);
    if (!t_ || !t_->contains(key)) fail(path(key) + " is required");
    return *t_->get(key);
  }
  double number(const std::string& key) { return as_number(node(key), path(key)); }
  double number(const std::string& key, double fallback) { return has(key) ? number(key) : fallback; }
  std::optional<double> optional_number(const std::string& key) {
    if (!has(key)) return std::nullopt;
    return number(key);
  }
  long integer(const std::string& key, long fallback) {
    if (!has(key)) return fallback;
    const toml::node& n = node(key);
    if (!n.is_integer()) fail(path(key) + " must be an integer, got " + type_name(n) + " " + shown(n));
    return static_cast<long>(*n.value<int64_t>());
  }
  std::string string(const std::string& key, const std::string& fallback) {
    if (!has(key)) return fallback;
    const toml::node& n = node(key);
    if (!n.is_string()) fail(path(key) + " must be a string, got " + type_name(n) + " " + shown(n));
    return *n.value<std::string>();
  }
  bool boolean(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    const toml::node& n = node(key);
    if (!n.is_boolean()) fail(path(key) + " must be true or false, got " + type_name(n) + " " + shown(n));
    return *n.value<bool>();
  }
  std::vector<double> numbers(const std::string& key) {
    const toml::node& n = node(key);
    const toml::array* a = n.as_array();
    if (!a) fail(path(key) + " must be an array of numbers, got " + type_name(n) + " " + shown(n));
    std::vector<double> out;
    for (std::size_t i = 0; i < a->size(); ++i)
      out.push_back(as_number(*a->get(i), path(key) + "[" + std::to_string(i) + "]"));
    return out;
  }
  Eigen::Vector3d vector3(const std::string& key) {
    const std::vector<double> v = numbers(key);
    if (v.size() != 3) fail(path(key) + " must have 3 components, got " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
  }
  Eigen::Vector3d vector3(const std::string& key, const Eigen::Vector3d& fallback) {
    return has(key) ? vector3(key) : fallback;
  }

  void check_no_unknown_keys(const std::vector<std::string>& allowed_hint) const {
    if (!t_) return;
    for (const auto& [k, v] : *t_) {
      const std::string key(k.str());
      if (used_.count(key)) continue;
      std::string known;
      for (const auto& a : allowed_hint) known += (known.empty() ? "" : ", ") + a;
      fail("unknown key " + path(key) + (known.empty() ? "" : " (known keys of [" + name_ + "]: " + known + ")"));
    }
  }

  static double as_number(const toml::node& n, const std::string& where) {
    if (n.is_floating_point()) return *n.value<double>();
    if (n.is_integer()) return static_cast<double>(*n.value<int64_t>());
    fail(where + " must be a number, got " + type_name(n) + " " + shown(n));
  }

 private:
  const toml::table* t_;
  std::string name_;
  std::set<std::string> used_;
};

const toml::table* section_table(const toml::table& root, const std::string& name, bool required) {
  const toml::node* n = root.get(name);
  if (!n) {
    if (required) fail("section [" + name + "] is required");
    return nullptr;
  }
  if (!n->is_table()) fail(name + " must be a section (table), got " + type_name(*n));
  return n->as_table();
}

void apply_override(toml::table& root, const std::string& assignment) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    fail("override '" + assignment + "' must have the form key=value (e.g. run.t_end=2)");
  const std::string key = assignment.substr(0, eq);
  const std::string value = assignment.substr(eq + 1);
  // Parse the value as TOML; if that fails it is a bare string (e.g. contact.law=exact).
  toml::table holder;
  try {
    holder = toml::parse("v = " + value);
  } catch (const toml::parse_error&) {
    holder = toml::table{};
    holder.insert("v", value);
  }
  toml::table* t = &root;
  std::string::size_type start = 0;
  for (;;) {
    const auto dot = key.find('.', start);
    const std::string part = key.substr(start, dot == std::string::npos ? std::string::npos : dot - start);
    if (part.empty()) fail("override key '" + key + "' has an empty part");
    if (dot == std::string::npos) {
      t->insert_or_assign(part, *holder.get("v"));
      return;
    }
    toml::node* n = t->get(part);
    if (!n) {
      t->insert(part, toml::table{});
      n = t->get(part);
    }
    if (!n->is_table()) fail("override key '" + key + "': " + key.substr(0, dot) + " is not a section");
    t = n->as_table();
    start = dot + 1;
  }
}

Scenario build(const toml::table& root, const std::string& source, const std::vector<std::string>& overrides) {
  Scenario s;
  s.source = source;
  s.overrides = overrides;

  Section top(&root, "");
  s.name = top.string("name", std::filesystem::path(source).stem().string());
  s.description = top.string("description", "");
  for (const char* sec : {"body", "contact", "initial", "run"}) (void)top.has(sec);
  top.check_no_unknown_keys({"name", "description", "[body]", "[contact]", "[initial]", "[run]"});

  // [body]
  Section body(section_table(root, "body", true), "body");
  if (body.has("profile")) s.body.preset = body.string("profile", "");
  if (body.has("chi2")) {
    s.body.chi2 = body.numbers("chi2");
    if (s.body.chi2.empty()) fail("body.chi2 must list at least one coefficient");
  }
  s.body.radius = body.optional_number("radius");
  if (body.has("semi_axes")) {
    const std::vector<double> ax = body.numbers("semi_axes");
    if (ax.size() != 2) fail("body.semi_axes must be [equatorial, polar], got " + std::to_string(ax.size()) + " values");
    s.body.semi_axes = std::array<double, 2>{ax[0], ax[1]};
  }
  s.body.mass = body.number("mass");
  s.body.com = body.optional_number("com");
  s.body.A = body.optional_number("A");
  s.body.C = body.optional_number("C");
  body.check_no_unknown_keys({"profile", "chi2", "radius", "semi_axes", "mass", "com", "A", "C"});
  const Body built = make_body(s.body);  // validates the profile and mass properties now

  // [contact]
  Section contact(section_table(root, "contact", true), "contact");
  s.contact.k = contact.number("k");
  s.contact.lambda = contact.number("lambda");
  s.contact.g = contact.number("g", 9.81);
  s.law = contact.string("law", "exact");
  contact.check_no_unknown_keys({"k", "lambda", "g", "law"});
  s.contact.validate();

  // [initial]
  Section init(section_table(root, "initial", true), "initial");
  const Eigen::Vector3d gamma = init.vector3("gamma");
  const double len = gamma.norm();
  if (!(std::isfinite(len) && std::abs(len - 1.0) <= kGammaUnitTolerance)) {
    std::ostringstream m;
    m.precision(10);
    m << "initial.gamma = [" << gamma[0] << ", " << gamma[1] << ", " << gamma[2] << "] has length " << len
      << ": it must be a unit vector (within " << kGammaUnitTolerance << "; it is then normalised)";
    fail(m.str());
  }
  s.initial.gamma = gamma / len;
  s.initial.omega = init.vector3("omega", Eigen::Vector3d::Zero());
  s.initial.v = init.vector3("v", Eigen::Vector3d::Zero());
  const toml::node& eps = init.node("eps");
  if (eps.is_string()) {
    if (*eps.value<std::string>() != "static")
      fail("initial.eps must be a number (m) or \"static\", got \"" + *eps.value<std::string>() + "\"");
    s.initial.eps = s.contact.static_height(built.mass * s.contact.g);
  } else {
    s.initial.eps = Section::as_number(eps, "initial.eps");
  }
  for (const auto& [what, value] : {std::pair{"initial.omega", s.initial.omega}, std::pair{"initial.v", s.initial.v}})
    if (!value.allFinite()) fail(std::string(what) + " must be finite");
  if (!std::isfinite(s.initial.eps)) fail("initial.eps must be finite");
  init.check_no_unknown_keys({"gamma", "omega", "v", "eps"});

  // [run]
  Section run(section_table(root, "run", true), "run");
  RunOptions& r = s.run;
  r.t_end = run.number("t_end");
  r.output_dt = run.number("output_dt", 1e-3);
  r.max_samples = run.integer("max_samples", r.max_samples);
  r.integrator.method = run.string("integrator", r.integrator.method);
  r.integrator.abs_tol = run.number("abs_tol", r.integrator.abs_tol);
  r.integrator.rel_tol = run.number("rel_tol", r.integrator.rel_tol);
  r.integrator.initial_step = run.number("initial_step", r.integrator.initial_step);
  r.integrator.max_step = run.number("max_step", r.integrator.max_step);
  r.integrator.max_steps = run.integer("max_steps", r.integrator.max_steps);
  // Unset thresholds take defaults scaled to the body (dynamics/rest_event.h, dynamics/settling.h).
  r.rest.slip_speed = run.optional_number("rest_slip_speed");
  r.rest.spin = run.optional_number("rest_spin");
  r.rest.kinetic_energy = run.optional_number("rest_kinetic_energy");
  r.settle.time = run.optional_number("settle_time");
  r.settle.normal_speed = run.optional_number("settle_normal_speed");
  r.stop_when_rolling = run.boolean("stop_when_rolling", r.stop_when_rolling);
  r.max_stagnant_steps = run.integer("max_stagnant_steps", r.max_stagnant_steps);
  run.check_no_unknown_keys({"t_end", "output_dt", "max_samples", "integrator", "abs_tol", "rel_tol", "initial_step",
                             "max_step", "max_steps", "rest_slip_speed", "rest_spin", "rest_kinetic_energy",
                             "settle_time", "settle_normal_speed", "stop_when_rolling", "max_stagnant_steps"});
  r.validate();

  std::ostringstream resolved;
  resolved << root;
  s.resolved_toml = resolved.str();
  return s;
}

}  // namespace

Scenario parse_scenario(std::string_view toml_text, const std::string& source, const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream m;
    m << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    fail(m.str());
  }
  for (const auto& o : overrides) apply_override(root, o);
  try {
    return build(root, source, overrides);
  } catch (const std::invalid_argument& e) {
    fail(source + ": " + e.what());
  }
}

Scenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::ifstream in(file);
  if (!in) fail("cannot read scenario file '" + file.string() + "'");
  std::stringstream buf;
  buf << in.rdbuf();
  return parse_scenario(buf.str(), file.string(), overrides);
}

StateVector initial_state(const Scenario& s) {
  return make_state(s.initial.v, s.initial.omega, s.initial.gamma, s.initial.eps);
}

}  // namespace frictionlab::dynamics
