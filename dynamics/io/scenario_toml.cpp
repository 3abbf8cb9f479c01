#include "dynamics/io/scenario_toml.h"

#include <algorithm>
#include <sstream>

#include "dynamics/io/toml_document.h"
#include "dynamics/io/toml_nesting.h"
#include "friction/law_spec.h"
#include "friction/registry.h"
#include "friction/support/errors.h"

namespace frictionlab::dynamics::scenario_toml {

void fail(const std::string& msg) { throw std::invalid_argument(msg); }
void fail_at(const std::string& key, const std::string& msg) { throw support::InvalidValue(key, msg); }

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

bool Section::has(const std::string& key) {
  used_.insert(key);
  return t_ && t_->contains(key);
}

const toml::node& Section::node(const std::string& key) {
  used_.insert(key);
  if (!t_ || !t_->contains(key)) fail_at(path(key), path(key) + " is required");
  return *t_->get(key);
}

double Section::number(const std::string& key) { return as_number(node(key), path(key)); }

double Section::number(const std::string& key, double fallback) { return has(key) ? number(key) : fallback; }

std::optional<double> Section::optional_number(const std::string& key) {
  if (!has(key)) return std::nullopt;
  return number(key);
}

long Section::integer(const std::string& key, long fallback) {
  if (!has(key)) return fallback;
  const toml::node& n = node(key);
  if (!n.is_integer()) fail_at(path(key), path(key) + " must be an integer, got " + type_name(n) + " " + shown(n));
  return static_cast<long>(*n.value<int64_t>());
}

std::string Section::string(const std::string& key, const std::string& fallback) {
  if (!has(key)) return fallback;
  const toml::node& n = node(key);
  if (!n.is_string()) fail_at(path(key), path(key) + " must be a string, got " + type_name(n) + " " + shown(n));
  return *n.value<std::string>();
}

bool Section::boolean(const std::string& key, bool fallback) {
  if (!has(key)) return fallback;
  const toml::node& n = node(key);
  if (!n.is_boolean()) fail_at(path(key), path(key) + " must be true or false, got " + type_name(n) + " " + shown(n));
  return *n.value<bool>();
}

std::vector<double> Section::numbers(const std::string& key) {
  const toml::node& n = node(key);
  const toml::array* a = n.as_array();
  if (!a) fail_at(path(key), path(key) + " must be an array of numbers, got " + type_name(n) + " " + shown(n));
  std::vector<double> out;
  for (std::size_t i = 0; i < a->size(); ++i) out.push_back(as_number(*a->get(i), path(key) + "[" + std::to_string(i) + "]"));
  return out;
}

std::vector<std::string> Section::strings(const std::string& key) {
  if (!has(key)) return {};
  const toml::node& n = node(key);
  if (n.is_string()) return {*n.value<std::string>()};
  const toml::array* a = n.as_array();
  if (!a) fail_at(path(key), path(key) + " must be an array of strings, got " + type_name(n) + " " + shown(n));
  std::vector<std::string> out;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::node& item = *a->get(i);
    if (!item.is_string()) {
      fail_at(path(key), path(key) + "[" + std::to_string(i) + "] must be a string, got " + type_name(item) + " " +
                             shown(item));
    }
    out.push_back(*item.value<std::string>());
  }
  return out;
}

std::vector<double> Section::numbers(const std::string& key, std::size_t n) {
  std::vector<double> v = numbers(key);
  if (v.size() != n)
    fail_at(path(key), path(key) + " must have " + std::to_string(n) + " components, got " + std::to_string(v.size()));
  return v;
}

Eigen::Vector3d Section::vector3(const std::string& key) {
  const std::vector<double> v = numbers(key, 3);
  return {v[0], v[1], v[2]};
}

Eigen::Vector3d Section::vector3(const std::string& key, const Eigen::Vector3d& fallback) {
  return has(key) ? vector3(key) : fallback;
}

void Section::check_no_unknown_keys(const std::vector<std::string>& allowed_hint) const {
  if (!t_) return;
  for (const auto& [k, v] : *t_) {
    const std::string key(k.str());
    if (used_.count(key)) continue;
    std::string known;
    for (const auto& a : allowed_hint) known += (known.empty() ? "" : ", ") + a;
    fail_at(path(key), "unknown key " + path(key) + (known.empty() ? "" : " (known keys of [" + name_ + "]: " + known + ")"));
  }
}

double Section::as_number(const toml::node& n, const std::string& where) {
  if (n.is_floating_point()) return *n.value<double>();
  if (n.is_integer()) return static_cast<double>(*n.value<int64_t>());
  fail_at(where, where + " must be a number, got " + type_name(n) + " " + shown(n));
}

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
  // The key's parts nest as tables ([run] t_end: 2 levels), the value may nest further: the
  // scenario after the override must still read back (dynamics/io/toml_nesting.h).
  const std::string holder_text = "v = " + value;
  const auto key_parts = static_cast<int>(std::count(key.begin(), key.end(), '.')) + 1;
  check_toml_nesting(key_parts - 1 + toml_nesting(holder_text).depth, "the key and value");
  // Parse the value as TOML; if that fails it is a bare string (e.g. contact.law=exact).
  std::optional<toml::table> parsed = try_parse_toml(holder_text, "the value");
  toml::table holder = parsed ? std::move(*parsed) : toml::table{};
  if (!parsed) holder.insert("v", value);
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

namespace {

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

}  // namespace

std::string blamed(const std::invalid_argument& e, const std::vector<std::string>& overrides, const std::string& source) {
  const std::string key = key_of(e);
  for (auto o = overrides.rbegin(); o != overrides.rend(); ++o) {
    const std::string_view set = std::string_view(*o).substr(0, o->find('='));
    if (!key.empty() && (within_key(key, set) || within_key(set, key))) return "--set " + *o;
  }
  return source;
}

RunOptions read_run(const toml::table& root, RunKeys keys) {
  Section run(section_table(root, "run", true), "run");
  RunOptions r;
  r.t_end = run.number("t_end");
  r.output_dt = run.number("output_dt", 1e-3);
  r.max_samples = run.integer("max_samples", r.max_samples);
  r.max_output_bytes = run.integer("max_output_bytes", r.max_output_bytes);
  r.integrator.method = run.string("integrator", r.integrator.method);
  r.integrator.abs_tol = run.number("abs_tol", r.integrator.abs_tol);
  r.integrator.rel_tol = run.number("rel_tol", r.integrator.rel_tol);
  r.integrator.initial_step = run.number("initial_step", r.integrator.initial_step);
  r.integrator.max_step = run.number("max_step", r.integrator.max_step);
  r.integrator.max_steps = run.integer("max_steps", r.integrator.max_steps);
  // Unset thresholds take defaults scaled to the body (dynamics/core/rest_event.h, dynamics/core/settling.h).
  r.rest.slip_speed = run.optional_number("rest_slip_speed");
  r.rest.spin = run.optional_number("rest_spin");
  // Shadow laws (dynamics/core/shadow_laws.h): each item a law spec or a list of them.
  for (const std::string& item : run.strings("shadow")) {
    std::vector<std::string> specs;
    try {
      specs = friction::split_law_list(item);
    } catch (const std::invalid_argument& e) {
      throw support::invalid_value("run.shadow", std::string_view(item), e.what());
    }
    for (const std::string& spec : specs) {
      check_law_spec("run.shadow", spec);
      r.shadow.push_back(spec);
    }
  }
  std::vector<std::string> known = {"t_end",        "output_dt", "max_samples",     "max_output_bytes", "integrator",
                                    "abs_tol",      "rel_tol",   "initial_step",    "max_step",         "max_steps",
                                    "rest_slip_speed", "rest_spin", "shadow"};
  if (keys == RunKeys::body) {
    r.rest.kinetic_energy = run.optional_number("rest_kinetic_energy");
    r.settle.time = run.optional_number("settle_time");
    r.settle.normal_speed = run.optional_number("settle_normal_speed");
    r.stop_when_rolling = run.boolean("stop_when_rolling", r.stop_when_rolling);
    r.max_stagnant_steps = run.integer("max_stagnant_steps", r.max_stagnant_steps);
    r.stick = run.boolean("stick", r.stick);
    r.slip_hold = run.boolean("slip_hold", r.slip_hold);
    r.pose = run.boolean("pose", r.pose);
    r.stick_hold_time = run.optional_number("stick_hold_time");
    r.chatter.max_steps = run.integer("max_chatter_steps", r.chatter.max_steps);
    r.chatter.step = run.optional_number("chatter_step");
    known.insert(known.end(), {"rest_kinetic_energy", "settle_time", "settle_normal_speed", "stop_when_rolling",
                               "max_stagnant_steps", "max_chatter_steps", "chatter_step", "stick",
                               "slip_hold", "stick_hold_time", "pose"});
  }
  run.check_no_unknown_keys(known);
  r.validate();
  return r;
}

std::string model_of(const toml::table& root) {
  const toml::node* n = root.get("model");
  if (!n) return "body";
  if (!n->is_string()) fail_at("model", "model must be a string (\"body\" or \"puck\"), got " + type_name(*n) + " " + shown(*n));
  const std::string m = *n->value<std::string>();
  if (m != "body" && m != "puck")
    throw support::invalid_value("model", std::string_view(m),
                                 "it must be \"body\" (a body of revolution on a Hertz plane) or \"puck\" (a flat "
                                 "body sliding and spinning on a fixed patch)");
  return m;
}

void check_law_spec(const std::string& key, const std::string& spec) {
  try {
    (void)friction::make_law(spec);
  } catch (const std::invalid_argument& e) {
    throw support::invalid_value(key, std::string_view(spec), e.what());
  }
}

}  // namespace frictionlab::dynamics::scenario_toml
