#include "dynamics/simulation.h"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>
#include <stdexcept>

#include "friction/gsl_error_policy.h"

namespace frictionlab::dynamics {
namespace {

struct Method {
  const char* name;
  const gsl_odeiv2_step_type* const* type;
};

const std::vector<Method>& methods() {
  static const std::vector<Method> all = {
      {"rk8pd", &gsl_odeiv2_step_rk8pd}, {"rkck", &gsl_odeiv2_step_rkck}, {"rkf45", &gsl_odeiv2_step_rkf45},
      {"rk4", &gsl_odeiv2_step_rk4},     {"rk2", &gsl_odeiv2_step_rk2},   {"msadams", &gsl_odeiv2_step_msadams},
  };
  return all;
}

std::string num(double x) {
  std::ostringstream s;
  s.precision(10);
  s << x;
  return s.str();
}

[[noreturn]] void fail(const char* key, double value, const char* rule) {
  throw std::invalid_argument(std::string(key) + " = " + num(value) + " is invalid: " + rule);
}

// What the GSL callback needs; counts calls and records why an evaluation failed.
struct Context {
  const BodyOnPlane* sys = nullptr;
  long rhs_calls = 0;
  bool nonfinite = false;  // the last failure was a non-finite value (retry with a smaller step)
  std::string message;     // what went wrong, for the summary
};

// The friction at a state, in one line (for failure messages only).
std::string describe_friction(const BodyOnPlane& sys, const StateVector& x) {
  std::ostringstream m;
  m.precision(10);
  try {
    const ContactState c = sys.contact_state(x);
    m << "friction law '" << sys.law().name() << "' gives F1 = " << c.friction.F1 << " N, F2 = " << c.friction.F2
      << " N, M = " << c.friction.M << " N m at U = " << c.U << " m/s, Omega = " << c.Omega << " 1/s, a = " << c.a
      << " m, b = " << c.b << " m, psi = " << c.psi << ", N = " << c.N << " N";
  } catch (const std::exception& e) {
    m << e.what();
  }
  return m.str();
}

std::string describe_nonfinite(const BodyOnPlane& sys, double t, const StateVector& x) {
  std::ostringstream m;
  m.precision(10);
  m << "the right-hand side is not finite at t = " << t << " s";
  if (!x.allFinite()) {
    m << " (the trial state is not finite)";
    return m.str();
  }
  m << ": " << describe_friction(sys, x);
  return m.str();
}

int rhs(double t, const double y[], double f[], void* params) {
  auto& ctx = *static_cast<Context*>(params);
  ++ctx.rhs_calls;
  const StateVector x = Eigen::Map<const StateVector>(y);
  if (!x.allFinite()) {
    ctx.nonfinite = true;
    ctx.message = describe_nonfinite(*ctx.sys, t, x);
    return GSL_FAILURE;
  }
  StateVector d;
  try {
    (*ctx.sys)(t, x, d);
  } catch (const std::exception& e) {
    ctx.nonfinite = false;
    ctx.message = std::string("at t = ") + num(t) + " s: " + e.what();
    return GSL_EBADFUNC;
  }
  if (!d.allFinite()) {
    ctx.nonfinite = true;
    ctx.message = describe_nonfinite(*ctx.sys, t, x);
    return GSL_FAILURE;
  }
  Eigen::Map<StateVector> out(f);
  out = d;
  return GSL_SUCCESS;
}

struct DriverDeleter {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

}  // namespace

std::vector<std::string> integrator_methods() {
  std::vector<std::string> out;
  for (const auto& m : methods()) out.emplace_back(m.name);
  return out;
}

void IntegratorOptions::validate() const {
  bool known = false;
  for (const auto& m : methods()) known = known || method == m.name;
  if (!known) {
    std::string list;
    for (const auto& m : integrator_methods()) list += (list.empty() ? "" : ", ") + m;
    throw std::invalid_argument("run.integrator = '" + method + "' is not a known stepper; known: " + list);
  }
  if (!(std::isfinite(abs_tol) && abs_tol > 0.0)) fail("run.abs_tol", abs_tol, "it must be finite and > 0");
  if (!(std::isfinite(rel_tol) && rel_tol >= 0.0)) fail("run.rel_tol", rel_tol, "it must be finite and >= 0");
  if (!(std::isfinite(initial_step) && initial_step > 0.0))
    fail("run.initial_step", initial_step, "it must be finite and > 0 s");
  if (!(std::isfinite(max_step) && max_step >= 0.0))
    fail("run.max_step", max_step, "it must be finite and >= 0 s (0: no limit)");
  if (max_steps <= 0) fail("run.max_steps", static_cast<double>(max_steps), "it must be > 0");
}

void RunOptions::validate() const {
  if (!(std::isfinite(t_end) && t_end > 0.0)) fail("run.t_end", t_end, "it must be finite and > 0 s");
  if (!(std::isfinite(output_dt) && output_dt > 0.0))
    fail("run.output_dt", output_dt, "it must be finite and > 0 s");
  integrator.validate();
  rest.validate();
}

std::string_view to_string(Termination t) {
  switch (t) {
    case Termination::t_end: return "t_end";
    case Termination::rest: return "rest";
    case Termination::rolling: return "rolling";
    case Termination::non_finite: return "non-finite";
    case Termination::law_error: return "law-error";
    case Termination::integrator_failure: return "integrator-failure";
    case Termination::max_steps: return "max-steps";
    case Termination::interrupted: return "interrupted";
  }
  return "unknown";
}

RunSummary simulate(const BodyOnPlane& sys, const StateVector& x0, const RunOptions& options, Observer* observer) {
  options.validate();
  if (!x0.allFinite()) throw std::invalid_argument("the initial state is not finite");
  use_gsl_status_codes();

  const auto wall_start = std::chrono::steady_clock::now();
  const IntegratorOptions& io = options.integrator;
  const gsl_odeiv2_step_type* type = nullptr;
  for (const auto& m : methods())
    if (io.method == m.name) type = *m.type;

  Context ctx;
  ctx.sys = &sys;
  gsl_odeiv2_system system{&rhs, nullptr, StateLayout::kSize, &ctx};
  std::unique_ptr<gsl_odeiv2_driver, DriverDeleter> driver(
      gsl_odeiv2_driver_alloc_y_new(&system, type, io.initial_step, io.abs_tol, io.rel_tol));
  if (!driver) throw std::runtime_error("GSL could not allocate the integrator");

  RunSummary s;
  StateVector x = x0;
  double t = 0.0;
  double h = io.initial_step;
  const double max_step = io.max_step > 0.0 ? io.max_step : std::numeric_limits<double>::infinity();

  const auto emit = [&](double time, const StateVector& state) {
    if (!observer) return;
    const ContactState c = sys.contact_state(state);
    observer->sample(Sample{time, state, c, sys.energy(state, c), sys.kinetic_energy(state)});
  };
  const auto stop = [&](Termination why, std::string message) {
    s.reason = why;
    s.message = std::move(message);
  };

  ContactState c0 = sys.contact_state(x);  // throws here (not mid-run) if the law rejects x0
  s.initial_energy = sys.energy(x, c0);
  s.min_normal_force = c0.N;
  s.max_gamma_drift = std::abs(vertical(x).norm() - 1.0);
  bool in_contact = c0.in_contact;
  emit(t, x);
  long next_sample = 1;
  bool sampled_last = true;
  bool done = false;

  while (!done) {
    if (t >= options.t_end) {
      stop(Termination::t_end, "");
      break;
    }
    const double t_sample = std::min(static_cast<double>(next_sample) * options.output_dt, options.t_end);
    const StateVector x_good = x;
    const double t_good = t;
    const double h_before = h = std::min(h, max_step);
    ctx.nonfinite = false;
    const int status = gsl_odeiv2_evolve_apply(driver->e, driver->c, driver->s, &system, &t, t_sample, &h, x.data());
    if (status == GSL_SUCCESS) {
      ++s.steps;
      if (!x.allFinite()) {
        x = x_good;
        t = t_good;
        stop(Termination::non_finite, "the state became non-finite after the step from t = " + num(t_good) + " s");
        break;
      }
      // A step shortened to land on a sample time should not shrink the next one.
      if (t == t_sample && h < h_before) h = h_before;
      sampled_last = false;
      if (t == t_sample) {
        emit(t, x);
        sampled_last = true;
        ++next_sample;
      }
      if (observer) observer->step(t);

      // Events between steps.
      const ContactState c = sys.contact_state(x);
      if (c.in_contact != in_contact) (c.in_contact ? s.landings : s.liftoffs) += 1;
      in_contact = c.in_contact;
      s.min_normal_force = std::min(s.min_normal_force, c.N);
      s.max_gamma_drift = std::max(s.max_gamma_drift, std::abs(vertical(x).norm() - 1.0));
      const double kinetic = sys.kinetic_energy(x);
      if (options.rest.at_rest(c.in_contact, c.U, c.Omega, kinetic)) {
        stop(Termination::rest, "slip speed, spin and kinetic energy fell below the rest thresholds");
        done = true;
      } else if (options.stop_when_rolling && options.rest.contact_stagnant(c.in_contact, c.U, c.Omega)) {
        stop(Termination::rolling, "the contact neither slips (U = " + num(c.U) + " m/s) nor spins (Omega = " +
                                       num(c.Omega) + " 1/s) but the kinetic energy " + num(kinetic) +
                                       " J is above run.rest_kinetic_energy: the body rolls without slip");
        done = true;
      } else if (s.steps >= io.max_steps) {
        stop(Termination::max_steps, "run.max_steps = " + std::to_string(io.max_steps) + " steps reached");
        done = true;
      } else if (options.cancel && options.cancel->load(std::memory_order_relaxed)) {
        stop(Termination::interrupted, "interrupted");
        done = true;
      }
    } else if (status == GSL_EBADFUNC) {
      x = x_good;
      t = t_good;
      stop(Termination::law_error, ctx.message);
      break;
    } else {
      // GSL already retried with ever smaller steps down to machine precision.
      x = x_good;
      t = t_good;
      if (ctx.nonfinite) {
        stop(Termination::non_finite, ctx.message + " (no step size down to machine precision avoids it)");
      } else {
        stop(Termination::integrator_failure,
             std::string("GSL: ") + gsl_strerror(status) + " (no step above machine precision meets the tolerance) at t = " +
                 num(t) + " s; at that state " + describe_friction(sys, x));
      }
      break;
    }
  }

  if (!sampled_last) emit(t, x);
  s.t_final = t;
  s.x_final = x;
  s.rhs_calls = ctx.rhs_calls;
  s.rejected_steps = static_cast<long>(driver->e->failed_steps);
  s.final_energy = sys.energy(x);
  s.wall_time = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  return s;
}

}  // namespace frictionlab::dynamics
