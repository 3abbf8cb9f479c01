#include "dynamics/scenario.h"

#include <toml++/toml.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "dynamics/scenario_limits.h"
#include "friction/registry.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics {
namespace {

[[noreturn]] void fail(const std::string& msg) { throw std::invalid_argument(msg); }
// An error about one key (so that resolve() can tell whether an override set it).
[[noreturn]] void fail_at(const std::string& key, const std::string& msg) { throw support::InvalidValue(key, msg); }

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
    if (!t_ || !t_->contains(key)) fail_at(path(key), path(key) + " is required");
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
    if (!n.is_integer()) fail_at(path(key), path(key) + " must be an integer, got " + type_name(n) + " " + shown(n));
    return static_cast<long>(*n.value<int64_t>());
  }
  std::string string(const std::string& key, const std::string& fallback) {
    if (!has(key)) return fallback;
    const toml::node& n = node(key);
    if (!n.is_string()) fail_at(path(key), path(key) + " must be a string, got " + type_name(n) + " " + shown(n));
    return *n.value<std::string>();
  }
  bool boolean(const std::string& key, bool fallback) {
    if (!has(key)) return fallback;
    const toml::node& n = node(key);
    if (!n.is_boolean()) fail_at(path(key), path(key) + " must be true or false, got " + type_name(n) + " " + shown(n));
    return *n.value<bool>();
  }
  std::vector<double> numbers(const std::string& key) {
    const toml::node& n = node(key);
    const toml::array* a = n.as_array();
    if (!a) fail_at(path(key), path(key) + " must be an array of numbers, got " + type_name(n) + " " + shown(n));
    std::vector<double> out;
    for (std::size_t i = 0; i < a->size(); ++i)
      out.push_back(as_number(*a->get(i), path(key) + "[" + std::to_string(i) + "]"));
    return out;
  }
  Eigen::Vector3d vector3(const std::string& key) {
    const std::vector<double> v = numbers(key);
    if (v.size() != 3) fail_at(path(key), path(key) + " must have 3 components, got " + std::to_string(v.size()));
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
      fail_at(path(key), "unknown key " + path(key) + (known.empty() ? "" : " (known keys of [" + name_ + "]: " + known + ")"));
    }
  }

  static double as_number(const toml::node& n, const std::string& where) {
    if (n.is_floating_point()) return *n.value<double>();
    if (n.is_integer()) return static_cast<double>(*n.value<int64_t>());
    fail_at(where, where + " must be a number, got " + type_name(n) + " " + shown(n));
  }

 private:
  const toml::table* t_;
  std::string name_;
  std::set<std::string> used_;
};

const toml::table* section_table(const toml::table& root, const std::string& name, bool required) {
  const toml::node* n = root.get(name);
  if (!n) {
    if (required) fail_at(name, "section [" + name + "] is required");
    return nullptr;
  }
  if (!n->is_table()) fail_at(name, name + " must be a section (table), got " + type_name(*n));
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

// Reads [body] as written (the body itself is built from it once, by the caller).
BodySpec read_body_spec(const toml::table& root) {
  BodySpec spec;
  Section body(section_table(root, "body", true), "body");
  if (body.has("profile")) spec.preset = body.string("profile", "");
  if (body.has("chi2")) {
    spec.chi2 = body.numbers("chi2");
    if (spec.chi2.empty()) fail_at("body.chi2", "body.chi2 must list at least one coefficient");
  }
  spec.radius = body.optional_number("radius");
  if (body.has("semi_axes")) {
    const std::vector<double> ax = body.numbers("semi_axes");
    if (ax.size() != 2) fail_at("body.semi_axes", "body.semi_axes must be [equatorial, polar], got " + std::to_string(ax.size()) + " values");
    spec.semi_axes = std::array<double, 2>{ax[0], ax[1]};
  }
  spec.mass = body.number("mass");
  spec.com = body.optional_number("com");
  spec.A = body.optional_number("A");
  spec.C = body.optional_number("C");
  body.check_no_unknown_keys({"profile", "chi2", "radius", "semi_axes", "mass", "com", "A", "C"});
  return spec;
}

// The law is a spec (friction/law_spec.h), kept verbatim; the registry says what is wrong with it.
void check_law(const std::string& law) {
  try {
    (void)friction::make_law(law);
  } catch (const std::invalid_argument& e) {
    throw support::invalid_value("contact.law", std::string_view(law), e.what());
  }
}

// The scenario after overrides as TOML, with what was left to defaults that a rerun from another
// file name would resolve differently (the name) or that defines the run (the law) written out.
std::string resolved_text(toml::table root, const std::string& name, const std::string& law) {
  root.insert_or_assign("name", name);
  if (toml::table* contact = root["contact"].as_table()) contact->insert_or_assign("law", law);
  std::ostringstream out;
  out << root;
  return out.str();
}

Scenario build(const toml::table& root, const std::string& source, const std::vector<std::string>& overrides) {
  Section top(&root, "");
  const std::string name = top.string("name", std::filesystem::path(source).stem().string());
  const std::string description = top.string("description", "");
  for (const char* sec : {"body", "contact", "initial", "run"}) (void)top.has(sec);
  top.check_no_unknown_keys({"name", "description", "[body]", "[contact]", "[initial]", "[run]"});

  // [body]: read, then built once (make_body validates the profile and the mass properties).
  BodySpec spec = read_body_spec(root);
  check_body_spec(spec);
  Body built = make_body(spec);
  const BodyExtent extent = extent_of(built);
  check_body(spec, built, extent);
  Scenario s{.name = name,
             .description = description,
             .source = source,
             .overrides = overrides,
             .body_spec = std::move(spec),
             .body = std::move(built),
             .contact = {},
             .law = {},
             .initial = {},
             .run = {},
             .resolved_toml = {}};

  // [contact]
  Section contact(section_table(root, "contact", true), "contact");
  s.contact.k = contact.number("k");
  s.contact.lambda = contact.number("lambda");
  s.contact.g = contact.number("g", 9.81);
  s.law = contact.string("law", "exact");
  contact.check_no_unknown_keys({"k", "lambda", "g", "law"});
  s.contact.validate();
  check_contact(s.contact, s.body, extent);
  check_law(s.law);

  // [initial]
  Section init(section_table(root, "initial", true), "initial");
  const Eigen::Vector3d gamma = init.vector3("gamma");
  const double len = gamma.norm();
  if (!(std::isfinite(len) && std::abs(len - 1.0) <= kGammaUnitTolerance)) {
    std::ostringstream m;
    m.precision(10);
    m << "initial.gamma = [" << gamma[0] << ", " << gamma[1] << ", " << gamma[2] << "] has length " << len
      << ": it must be a unit vector (within " << kGammaUnitTolerance << "; it is then normalised)";
    fail_at("initial.gamma", m.str());
  }
  s.initial.gamma = gamma / len;
  s.initial.omega = init.vector3("omega", Eigen::Vector3d::Zero());
  s.initial.v = init.vector3("v", Eigen::Vector3d::Zero());
  const toml::node& eps = init.node("eps");
  if (eps.is_string()) {
    if (*eps.value<std::string>() != "static")
      fail_at("initial.eps", "initial.eps must be a number (m) or \"static\", got \"" + *eps.value<std::string>() + "\"");
    s.initial.eps = s.contact.static_height(s.body.mass * s.contact.g);
  } else {
    s.initial.eps = Section::as_number(eps, "initial.eps");
  }
  for (const auto& [what, value] : {std::pair{"initial.omega", s.initial.omega}, std::pair{"initial.v", s.initial.v}})
    if (!value.allFinite()) fail_at(what, std::string(what) + " must be finite");
  if (!std::isfinite(s.initial.eps)) fail_at("initial.eps", "initial.eps must be finite");
  init.check_no_unknown_keys({"gamma", "omega", "v", "eps"});
  check_initial(s.initial.v, s.initial.omega, s.initial.eps, extent);

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

  s.resolved_toml = resolved_text(root, s.name, s.law);
  return s;
}

// The key an error is about: the one it carries, else (messages of the modules that check
// values, "run.t_end = -1 is invalid: ...") its first word.
std::string key_of(const std::invalid_argument& e) {
  if (const auto* v = dynamic_cast<const support::InvalidValue*>(&e)) return v->key();
  const std::string_view m = e.what();
  return std::string(m.substr(0, m.find(' ')));
}

// `inner` is `outer` or lies below it ("initial.omega[2]" below "initial.omega").
bool within_key(std::string_view inner, std::string_view outer) {
  return inner.substr(0, outer.size()) == outer &&
         (inner.size() == outer.size() || inner[outer.size()] == '.' || inner[outer.size()] == '[');
}

// Who set the value an error is about: the last override of its key ("--set key=value"), or the
// file.
std::string blamed(const std::invalid_argument& e, const std::vector<std::string>& overrides, const std::string& source) {
  const std::string key = key_of(e);
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
    const std::string_view set = std::string_view(*o).substr(0, o->find('='));
    if (!key.empty() && (within_key(key, set) || within_key(set, key))) return "--set " + *o;
  }
  return source;
}

}  // namespace

struct ScenarioDocument::Parsed {
  toml::table root;
};

ScenarioDocument::ScenarioDocument(std::shared_ptr<const Parsed> parsed, std::string source)
    : parsed_(std::move(parsed)), source_(std::move(source)) {}

ScenarioDocument ScenarioDocument::parse(std::string_view toml_text, const std::string& source) {
  auto parsed = std::make_shared<Parsed>();
  try {
    parsed->root = toml::parse(toml_text, source);
  } catch (const toml::parse_error& e) {
    std::ostringstream m;
    m << source << ":" << e.source().begin.line << ":" << e.source().begin.column << ": " << e.description();
    fail(m.str());
  }
  return ScenarioDocument(std::move(parsed), source);
}

ScenarioDocument ScenarioDocument::read(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    fail("scenario file '" + file.string() + "' is a folder: give the path of a .toml file");
  std::ifstream in(file, std::ios::binary);
  if (!in) fail("cannot read scenario file '" + file.string() + "': " + std::strerror(errno));
  std::stringstream buf;
  buf << in.rdbuf();
  if (in.bad()) fail("cannot read scenario file '" + file.string() + "': " + std::strerror(errno));
  return parse(buf.str(), file.string());
}

Scenario ScenarioDocument::resolve(const std::vector<std::string>& overrides) const {
  toml::table root = parsed_->root;
  for (const auto& o : overrides) {
    try {
      apply_override(root, o);
    } catch (const std::invalid_argument& e) {
      fail("--set " + o + ": " + e.what());
    }
  }
  try {
    return build(root, source_, overrides);
  } catch (const std::invalid_argument& e) {
    fail(blamed(e, overrides, source_) + ": " + e.what());
  }
}

Scenario parse_scenario(std::string_view toml_text, const std::string& source, const std::vector<std::string>& overrides) {
  return ScenarioDocument::parse(toml_text, source).resolve(overrides);
}

Scenario load_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return ScenarioDocument::read(file).resolve(overrides);
}

StateVector initial_state(const Scenario& s) {
  return make_state(s.initial.v, s.initial.omega, s.initial.gamma, s.initial.eps);
}

}  // namespace frictionlab::dynamics
