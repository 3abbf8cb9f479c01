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

// body.inertia = [[J11, J12, J13], [J21, J22, J23], [J31, J32, J33]] (kg m^2).
Eigen::Matrix3d read_inertia(Section& body) {
  const toml::node& n = body.node("inertia");
  const auto bad = [&](const std::string& why) {
    fail_at("body.inertia", "body.inertia must be the full tensor [[J11, J12, J13], [J21, J22, J23], [J31, J32, J33]] "
                            "(kg m^2, shape axes, J_ij = -integral of xi_i xi_j dm for i != j): " + why);
  };
  const toml::array* rows = n.as_array();
  if (!rows || rows->size() != 3) bad("got " + scenario_toml::shown(n));
  Eigen::Matrix3d J;
  for (std::size_t i = 0; i < 3; ++i) {
    const toml::array* row = rows->get(i)->as_array();
    if (!row || row->size() != 3) bad("row " + std::to_string(i + 1) + " is " + scenario_toml::shown(*rows->get(i)));
    for (std::size_t k = 0; k < 3; ++k)
      J(static_cast<int>(i), static_cast<int>(k)) =
          Section::as_number(*row->get(k), "body.inertia[" + std::to_string(i) + "][" + std::to_string(k) + "]");
  }
  return J;
}

// Reads [body] as written (the body itself is built from it once, by the caller).
BodySpec read_body_spec(const toml::table& root) {
  BodySpec spec;
  const toml::table* table = section_table(root, "body", true);
  Section body(table, "body");
  std::string shape = body.string("shape", "");
  if (shape == "revolution") shape.clear();  // today's keys describe it
  spec.mass = body.number("mass");
  if (body.has("com")) {
    const toml::node& com = body.node("com");
    if (com.is_array()) spec.com_vector = body.vector3("com");
    else spec.com = body.number("com");
  }
  if (body.has("inertia")) spec.inertia = read_inertia(body);
  if (!shape.empty()) {
    // Another shape kind: every other key is one of its parameters (shapes/shape_registry.h checks them).
    spec.shape = shape;
    for (const auto& [k, v] : *table) {
      const std::string key(k.str());
      if (key == "shape" || key == "mass" || key == "com" || key == "inertia" || key == "A" || key == "C") continue;
      if (v.is_array()) spec.shape_parameters[key] = body.numbers(key);
      else spec.shape_parameters[key] = {body.number(key)};
    }
    spec.A = body.optional_number("A");
    spec.C = body.optional_number("C");
    return spec;
  }
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
  spec.A = body.optional_number("A");
  spec.C = body.optional_number("C");
  body.check_no_unknown_keys(
      {"shape", "profile", "chi2", "radius", "semi_axes", "mass", "com", "A", "C", "inertia"});
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
                         "\": this scenario is not a body on the plane (run it with frictionlab simulate)");
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
  // The pose at t = 0 (dynamics/body/state.h): on the plane, and the heading about the vertical.
  if (init.has("position")) {
    const std::vector<double> p = init.numbers("position", 2);
    s.initial.position = Eigen::Vector2d(p[0], p[1]);
    if (!s.initial.position.allFinite()) fail_at("initial.position", "initial.position must be finite");
  }
  s.initial.heading = init.number("heading", 0.0);
  if (!std::isfinite(s.initial.heading)) fail_at("initial.heading", "initial.heading must be finite");
  init.check_no_unknown_keys({"gamma", "omega", "v", "eps", "position", "heading"});
  check_initial(s.initial.v, s.initial.omega, s.initial.eps, extent);

  // [run]
  s.run = scenario_toml::read_run(root, scenario_toml::RunKeys::body);
  check_planned_output(s.run.t_end, s.run.output_dt, s.run.max_output_bytes, trajectory_header(s.run.pose).size(),
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
  StateVector x = make_state(s.initial.v, s.initial.omega, s.initial.gamma, s.initial.eps);
  position(x) = s.initial.position;
  orientation(x) = orientation_from(s.initial.gamma, s.initial.heading);
  return x;
}

}  // namespace frictionlab::dynamics
