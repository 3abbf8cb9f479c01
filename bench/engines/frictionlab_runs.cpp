#include "bench/engines/frictionlab_runs.h"

#include <Eigen/Geometry>
#include <cmath>
#include <limits>

#include "dynamics/body/equations_of_motion.h"
#include "dynamics/body/scenario.h"
#include "dynamics/body/scenario_run.h"
#include "dynamics/body/state.h"
#include "dynamics/puck/puck_equations.h"
#include "dynamics/puck/puck_scenario.h"
#include "dynamics/puck/puck_scenario_run.h"
#include "friction/support/number_format.h"

namespace frictionlab::engines {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The body's samples in world terms: the orientation turns body vectors into world ones.
class BodyRecorder final : public dynamics::Observer {
 public:
  explicit BodyRecorder(std::vector<engines::Sample>& out) : out_(out) {}
  void sample(const dynamics::Sample& s) override {
    const Eigen::Quaterniond q = dynamics::orientation_quaternion(s.x);
    const Eigen::Vector3d v = q * Eigen::Vector3d(dynamics::velocity(s.x));
    const Eigen::Vector3d w = q * Eigen::Vector3d(dynamics::angular_velocity(s.x));
    const auto p = dynamics::position(s.x);
    engines::Sample o;
    o.t = s.t;
    o.com = {p[0], p[1], kNaN};
    o.v = {v[0], v[1], v[2]};
    o.omega = {w[0], w[1], w[2]};
    o.orientation = {q.w(), q.x(), q.y(), q.z()};
    o.normal_force = s.contact.N;
    out_.push_back(o);
  }

 private:
  std::vector<engines::Sample>& out_;
};

class PuckRecorder final : public dynamics::puck::PuckObserver {
 public:
  PuckRecorder(std::vector<engines::Sample>& out, double weight) : out_(out), weight_(weight) {}
  void sample(const dynamics::puck::PuckSample& s) override {
    const auto p = dynamics::puck::position(s.x);
    const auto v = dynamics::puck::velocity(s.x);
    const double h = dynamics::puck::heading(s.x);
    engines::Sample o;
    o.t = s.t;
    o.com = {p[0], p[1], kNaN};
    o.v = {v[0], v[1], 0.0};
    o.omega = {0.0, 0.0, dynamics::puck::spin(s.x)};
    o.orientation = {std::cos(0.5 * h), 0.0, 0.0, std::sin(0.5 * h)};
    o.normal_force = weight_;
    out_.push_back(o);
  }

 private:
  std::vector<engines::Sample>& out_;
  double weight_;
};

std::string ended(std::string_view reason, double t) {
  return std::string(reason) + " at " + support::significant(t, 4) + " s";
}

}  // namespace

FrictionlabRun run_frictionlab(const Problem& problem, const std::string& law_spec,
                               const std::filesystem::path& out_dir, const std::vector<std::string>& overrides) {
  FrictionlabRun r;
  std::vector<std::string> sets = overrides;
  sets.push_back("contact.law=" + law_spec);
  if (problem.id == "puck") {
    const auto s = dynamics::puck::load_puck_scenario(problem.scenario, sets);
    PuckRecorder rec(r.run.samples, s.puck.mass * s.g);
    const auto run = dynamics::puck::run_puck_scenario(s, out_dir, &rec);
    r.ended = ended(dynamics::to_string(run.summary.reason), run.summary.t_final);
  } else {
    const auto s = dynamics::load_scenario(problem.scenario, sets);
    BodyRecorder rec(r.run.samples);
    const auto run = dynamics::run_scenario(s, out_dir, &rec);
    r.ended = ended(dynamics::to_string(run.summary.reason), run.summary.t_final);
  }
  r.run.notes = "frictionlab " + law_spec + ", Hertz plane of the scenario, adaptive rk8pd";
  return r;
}

}  // namespace frictionlab::engines
