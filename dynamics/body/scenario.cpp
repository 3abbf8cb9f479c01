#include "dynamics/body/scenario.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

#include "dynamics/core/output_limit.h"
#include "dynamics/contact/patch_model.h"
#include "dynamics/body/scenario_limits.h"
#include "dynamics/io/scenario_toml.h"
#include "dynamics/body/trajectory_csv.h"
#include "dynamics/io/toml_document.h"
#include "friction/registry.h"
#include "friction/support/checked_input.h"
#include "friction/support/errors.h"
#include "friction/support/number_format.h"

namespace frictionlab::dynamics {
namespace {

using scenario_toml::fail;
using scenario_toml::fail_at;
using scenario_toml::Section;
using scenario_toml::section_table;

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
  if (top.has("model") && scenario_toml::model_of(root) != "body")
    fail_at("model", "model = \"" + scenario_toml::model_of(root) +
                         "\": this scenario is not a body of revolution (run it with frictionlab simulate)");
  for (const char* sec : {"body", "contact", "initial", "run"}) (void)top.has(sec);
  top.check_no_unknown_keys({"name", "description", "model", "[body]", "[contact]", "[initial]", "[run]"});

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
  // The contact model and its stiffness (dynamics/contact/patch_model.h).
  const PatchModelSpec patch{.patch = contact.string("patch", "section"),
                             .lambda = contact.optional_number("lambda"),
                             .E1 = contact.optional_number("E1"),
                             .nu1 = contact.optional_number("nu1"),
                             .E2 = contact.optional_number("E2"),
                             .nu2 = contact.optional_number("nu2"),
                             .lambda_gamma3 = contact.optional_number("lambda_gamma3")};
  s.contact.g = contact.number("g", 9.81);
  s.law = contact.string("law", "exact");
  contact.check_no_unknown_keys({"k", "lambda", "g", "law", "patch", "E1", "nu1", "E2", "nu2", "lambda_gamma3"});
  apply_patch_model(patch, s.body, s.contact);
  s.contact.validate();
  check_contact(s.contact, s.body, extent);
  scenario_toml::check_law_spec("contact.law", s.law);

  // [initial]
  Section init(section_table(root, "initial", true), "initial");
  const Eigen::Vector3d gamma = init.vector3("gamma");
  const double len = gamma.norm();
  if (!(std::isfinite(len) && std::abs(len - 1.0) <= kGammaUnitTolerance)) {
    fail_at("initial.gamma", "initial.gamma = " + support::message_list({gamma.data(), 3}) + " has length " +
                                 support::message_number(len) + ": it must be a unit vector (within " +
                                 support::message_number(kGammaUnitTolerance) + "; it is then normalised)");
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
  s.run = scenario_toml::read_run(root, scenario_toml::RunKeys::body);
  check_planned_output(s.run.t_end, s.run.output_dt, s.run.max_output_bytes, trajectory_header().size(),
                       kMinTrajectoryRowBytes, "trajectory.csv");

  s.resolved_toml = resolved_text(root, s.name, s.law);
  return s;
}

}  // namespace

ScenarioDocument::ScenarioDocument(std::shared_ptr<const Parsed> parsed, std::string source)
    : parsed_(std::move(parsed)), source_(std::move(source)) {}

ScenarioDocument ScenarioDocument::parse(std::string_view toml_text, const std::string& source) {
  auto parsed = std::make_shared<Parsed>();
  parsed->root = parse_toml(toml_text, source);
  return ScenarioDocument(std::move(parsed), source);
}

ScenarioDocument ScenarioDocument::read(const std::filesystem::path& file) {
  return parse(support::read_file(file, "scenario file"), file.string());
}

Scenario ScenarioDocument::resolve(const std::vector<std::string>& overrides) const {
  toml::table root = parsed_->root;
  for (const auto& o : overrides) {
    try {
      scenario_toml::apply_override(root, o);
    } catch (const std::invalid_argument& e) {
      fail("--set " + o + ": " + e.what());
    }
  }
  try {
    return build(root, source_, overrides);
  } catch (const std::invalid_argument& e) {
    fail(scenario_toml::blamed(e, overrides, source_) + ": " + e.what());
  }
}

std::string ScenarioDocument::model(const std::vector<std::string>& overrides) const {
  toml::table root = parsed_->root;
  for (const auto& o : overrides) {
    try {
      scenario_toml::apply_override(root, o);
    } catch (const std::invalid_argument& e) {
      fail("--set " + o + ": " + e.what());
    }
  }
  try {
    return scenario_toml::model_of(root);
  } catch (const std::invalid_argument& e) {
    fail(scenario_toml::blamed(e, overrides, source_) + ": " + e.what());
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
