#include "dynamics/puck/puck_scenario.h"

#include <cmath>
#include <sstream>

#include "dynamics/core/output_limit.h"
#include "dynamics/puck/puck_trajectory_csv.h"
#include "dynamics/body/scenario_limits.h"
#include "dynamics/io/scenario_toml.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics::puck {
namespace {

using scenario_toml::fail;
using scenario_toml::Section;
using scenario_toml::section_table;

bool within(double x, double lo, double hi) { return std::isfinite(x) && x >= lo && x <= hi; }

std::string range(double lo, double hi, const char* unit) {
  return "it must be within [" + support::message_number(lo) + ", " + support::message_number(hi) + "] " + unit;
}

void check_ranges(const PuckScenario& s) {
  using L = ScenarioLimits;
  const Puck& p = s.puck;
  if (!within(p.mass, L::kMinMass, L::kMaxMass)) throw support::invalid_value("puck.mass", p.mass, range(L::kMinMass, L::kMaxMass, "kg"));
  if (!within(2.0 * p.a, L::kMinSize, L::kMaxSize))
    throw support::invalid_value("puck.a", p.a, "the patch's diameter 2a " + range(L::kMinSize, L::kMaxSize, "m"));
  if (!(std::isfinite(p.b) && p.b > 0.0 && p.b <= p.a && 2.0 * p.b >= L::kMinSize))
    throw support::invalid_value("puck.b", p.b,
                                 "it must be <= puck.a (the major axis is body x) and 2b >= " +
                                     support::message_number(L::kMinSize) + " m");
  const double kappa = p.inertia / (p.mass * p.a * p.a);
  if (!within(kappa, PuckLimits::kMinInertiaRatio, PuckLimits::kMaxInertiaRatio))
    throw support::invalid_value("puck.inertia", p.inertia,
                                 "I/(m a^2) = " + support::message_number(kappa) + " " +
                                     range(PuckLimits::kMinInertiaRatio, PuckLimits::kMaxInertiaRatio, ""));
  if (!within(s.k, 0.0, L::kMaxFriction)) throw support::invalid_value("contact.k", s.k, range(0.0, L::kMaxFriction, ""));
  if (!within(s.g, 0.0, L::kMaxGravity)) throw support::invalid_value("contact.g", s.g, range(0.0, L::kMaxGravity, "m/s^2"));
  const double vmax = L::kMaxSpeed;
  if (!(s.initial.v.allFinite() && s.initial.v.norm() <= vmax))
    throw support::invalid_value("initial.v", std::span<const double>(s.initial.v.data(), 2),
                                 "|v| must be finite and <= " + support::message_number(vmax) + " m/s");
  if (!(std::isfinite(s.initial.omega) && std::abs(s.initial.omega) * p.a <= vmax))
    throw support::invalid_value("initial.omega", s.initial.omega,
                                 "|omega| a must be finite and <= " + support::message_number(vmax) + " m/s");
  if (!std::isfinite(s.initial.heading)) throw support::invalid_value("initial.heading", s.initial.heading, "it must be finite");
  if (!(s.initial.position.allFinite() && s.initial.position.norm() <= 1e6))
    throw support::invalid_value("initial.position", std::span<const double>(s.initial.position.data(), 2),
                                 "it must be finite and within 1e6 m of the origin");
}

std::string resolved_text(toml::table root, const std::string& name, const std::string& law) {
  root.insert_or_assign("name", name);
  if (toml::table* contact = root["contact"].as_table()) contact->insert_or_assign("law", law);
  std::ostringstream out;
  out << root;
  return out.str();
}

PuckScenario build(const toml::table& root, const std::string& source, const std::vector<std::string>& overrides) {
  Section top(&root, "");
  PuckScenario s;
  s.name = top.string("name", std::filesystem::path(source).stem().string());
  s.description = top.string("description", "");
  s.source = source;
  s.overrides = overrides;
  (void)top.has("model");
  if (scenario_toml::model_of(root) != "puck") scenario_toml::fail_at("model", "model = \"puck\" is required for a puck scenario");
  for (const char* sec : {"puck", "contact", "initial", "run"}) (void)top.has(sec);
  top.check_no_unknown_keys({"name", "description", "model", "[puck]", "[contact]", "[initial]", "[run]"});

  Section puck(section_table(root, "puck", true), "puck");
  s.puck.mass = puck.number("mass");
  s.puck.a = puck.number("a");
  s.puck.b = puck.number("b", s.puck.a);
  s.inertia_given = puck.has("inertia");
  s.puck.inertia = s.inertia_given ? puck.number("inertia") : uniform_plate_inertia(s.puck.mass, s.puck.a, s.puck.b);
  puck.check_no_unknown_keys({"mass", "a", "b", "inertia"});

  Section contact(section_table(root, "contact", true), "contact");
  s.k = contact.number("k");
  s.g = contact.number("g", 9.81);
  s.law = contact.string("law", "exact");
  contact.check_no_unknown_keys({"k", "g", "law"});

  Section init(section_table(root, "initial", false), "initial");
  if (init.has("v")) {
    const auto v = init.numbers("v", 2);
    s.initial.v = {v[0], v[1]};
  }
  s.initial.omega = init.number("omega", 0.0);
  s.initial.heading = init.number("heading", 0.0);
  if (init.has("position")) {
    const auto p = init.numbers("position", 2);
    s.initial.position = {p[0], p[1]};
  }
  init.check_no_unknown_keys({"v", "omega", "heading", "position"});

  check_ranges(s);
  s.puck.validate();
  scenario_toml::check_law_spec("contact.law", s.law);
  s.run = scenario_toml::read_run(root, scenario_toml::RunKeys::puck);
  check_planned_output(s.run.t_end, s.run.output_dt, s.run.max_output_bytes, puck_trajectory_header().size(),
                       kMinPuckTrajectoryRowBytes, "trajectory.csv");
  s.resolved_toml = resolved_text(root, s.name, s.law);
  return s;
}

}  // namespace

PuckScenario resolve_puck(const ScenarioDocument& doc, const std::vector<std::string>& overrides) {
  toml::table root = doc.parsed().root;
  for (const auto& o : overrides) {
    try {
      scenario_toml::apply_override(root, o);
    } catch (const std::invalid_argument& e) {
      fail("--set " + o + ": " + e.what());
    }
  }
  try {
    return build(root, doc.source(), overrides);
  } catch (const std::invalid_argument& e) {
    fail(scenario_toml::blamed(e, overrides, doc.source()) + ": " + e.what());
  }
}

PuckScenario load_puck_scenario(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  return resolve_puck(ScenarioDocument::read(file), overrides);
}

PuckScenario parse_puck_scenario(std::string_view toml_text, const std::string& source,
                                 const std::vector<std::string>& overrides) {
  return resolve_puck(ScenarioDocument::parse(toml_text, source), overrides);
}

PuckState initial_state(const PuckScenario& s) {
  return make_puck_state(s.initial.position, s.initial.heading, s.initial.v, s.initial.omega);
}

}  // namespace frictionlab::dynamics::puck
