#include "dynamics/summary_json.h"

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace frictionlab::dynamics {
namespace {

std::string json_string(std::string_view s) {
  std::string out = "\"";
  for (const char ch : s) {
    switch (ch) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\t': out += "\\t"; break;
      case '\r': out += "\\r"; break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned>(static_cast<unsigned char>(ch)));
          out += buf;
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

std::string number(double x) {
  if (!std::isfinite(x)) return "null";
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string array(const double* x, int n) {
  std::string out = "[";
  for (int i = 0; i < n; ++i) out += (i ? ", " : "") + number(x[i]);
  return out + "]";
}

std::string vec3(const Eigen::Vector3d& v) { return array(v.data(), 3); }

// A tiny writer for one JSON object with nesting by indentation.
class Json {
 public:
  explicit Json(std::ostream& out) : out_(out) { out_ << "{"; }
  void key(std::string_view k, const std::string& raw_value) {
    out_ << (first_ ? "\n" : ",\n") << indent() << json_string(k) << ": " << raw_value;
    first_ = false;
  }
  void open(std::string_view k) {
    out_ << (first_ ? "\n" : ",\n") << indent() << json_string(k) << ": {";
    ++depth_;
    first_ = true;
  }
  void close() {
    --depth_;
    out_ << "\n" << indent() << "}";
    first_ = false;
  }
  void finish() { out_ << "\n}\n"; }

 private:
  std::string indent() const { return std::string(2 * static_cast<std::size_t>(depth_ + 1), ' '); }
  std::ostream& out_;
  int depth_ = 0;
  bool first_ = true;
};

}  // namespace

void write_summary_json(std::ostream& out, const Scenario& scenario, const Body& body, std::string_view law,
                        const RunSummary& s) {
  const double weight = body.mass * scenario.contact.g;
  const StateVector& x = s.x_final;
  Json j(out);
  j.open("scenario");
  j.key("name", json_string(scenario.name));
  j.key("source", json_string(scenario.source));
  std::string ov = "[";
  for (std::size_t i = 0; i < scenario.overrides.size(); ++i) ov += (i ? ", " : "") + json_string(scenario.overrides[i]);
  j.key("overrides", ov + "]");
  j.close();
  j.key("law", json_string(law));
  j.open("termination");
  j.key("reason", json_string(to_string(s.reason)));
  j.key("message", json_string(s.message));
  j.key("rule", json_string(s.rule));
  std::string th = "[";
  for (std::size_t i = 0; i < s.thresholds.size(); ++i) {
    const Threshold& t = s.thresholds[i];
    th += (i ? ", " : "") + std::string("{\"key\": ") + json_string(t.key) + ", \"value\": " + number(t.value) +
          ", \"unit\": " + json_string(t.unit) + ", \"source\": " + json_string(t.source) + "}";
  }
  j.key("thresholds", th + "]");
  j.close();
  j.key("final_time", number(s.t_final));
  j.key("t_end", number(scenario.run.t_end));
  j.key("steps", std::to_string(s.steps));
  j.key("rejected_steps", std::to_string(s.rejected_steps));
  j.key("rhs_calls", std::to_string(s.rhs_calls));
  j.key("samples", std::to_string(s.samples));
  j.key("sample_rhs_calls", std::to_string(s.sample_rhs_calls));
  j.key("hermite_samples", std::to_string(s.hermite_samples));
  j.key("wall_time_s", number(s.wall_time));
  j.key("liftoffs", std::to_string(s.liftoffs));
  j.key("landings", std::to_string(s.landings));
  j.key("min_N_over_mg", weight > 0.0 ? number(s.min_normal_force / weight) : "null");
  j.key("initial_energy", number(s.initial_energy));
  j.key("final_energy", number(s.final_energy));
  j.key("work_sliding", number(slide_work(x)));
  j.key("work_spinning", number(spin_work(x)));
  j.key("energy_balance_error", number(s.final_energy + slide_work(x) + spin_work(x) - s.initial_energy));
  j.key("max_gamma_drift", number(s.max_gamma_drift));
  j.open("final_state");
  j.key("t", number(s.t_final));
  j.key("gamma", vec3(vertical(x)));
  j.key("omega", vec3(angular_velocity(x)));
  j.key("v", vec3(velocity(x)));
  j.key("eps", number(height(x)));
  j.close();
  j.open("body");
  j.key("profile", json_string(scenario.body.preset.empty() ? "chi2" : scenario.body.preset));
  const auto& c = body.profile.chi2().coefficients();
  j.key("chi2", array(c.data(), static_cast<int>(c.size())));
  j.key("z_lo", number(body.profile.z_lo()));
  j.key("z_hi", number(body.profile.z_hi()));
  j.key("mass", number(body.mass));
  j.key("com", number(body.com));
  j.key("A", number(body.A));
  j.key("C", number(body.C));
  j.key("homogeneous_centroid", number(body.homogeneous.centroid));
  j.close();
  j.open("contact");
  j.key("k", number(scenario.contact.k));
  j.key("lambda", number(scenario.contact.lambda));
  j.key("g", number(scenario.contact.g));
  j.close();
  j.open("integrator");
  j.key("method", json_string(scenario.run.integrator.method));
  j.key("abs_tol", number(scenario.run.integrator.abs_tol));
  j.key("rel_tol", number(scenario.run.integrator.rel_tol));
  j.key("output_dt", number(scenario.run.output_dt));
  j.open("abs_tol_per_component");
  j.key("v", number(velocity(s.abs_tol)[0]));
  j.key("omega", number(angular_velocity(s.abs_tol)[0]));
  j.key("gamma", number(vertical(s.abs_tol)[0]));
  j.key("eps", number(height(s.abs_tol)));
  j.key("work", number(slide_work(s.abs_tol)));
  j.close();
  j.close();
  j.open("scales");
  j.key("size_R", number(s.scales.size));
  j.key("speed_sqrt_gR", number(s.scales.speed));
  j.key("rate_sqrt_g_over_R", number(s.scales.rate));
  j.key("energy_mgR", number(s.scales.energy));
  j.key("static_compression", number(s.scales.compression));
  j.key("liftoff_speed", number(s.scales.liftoff_speed));
  j.close();
  j.open("rest_thresholds");
  j.key("slip_speed", number(s.rest.slip_speed.value));
  j.key("spin", number(s.rest.spin.value));
  j.key("kinetic_energy", number(s.rest.kinetic_energy.value));
  j.key("settle_time", number(s.settle.time.value));
  j.key("settle_normal_speed", number(s.settle.normal_speed.value));
  j.close();
  j.finish();
}

}  // namespace frictionlab::dynamics
