// Cost of the body's right-hand side (dynamics/body/equations_of_motion.h) per call, and of its parts,
// on the states of the printed egg's case a (docs/model.md §6): the first 2 s of the run, sampled
// every 1e-3 s (the egg spins on its lower pole and rises, bouncing: 1023 of the 2001 states are
// in contact).
//
//   build/bench/dynamics_bench
//   build/bench/dynamics_bench --benchmark_filter='BM_rhs/exact'
//
// One iteration = one call, cycling through the 2001 states, so the reported time is the mean cost
// per call over the set. BM_rhs/<law> is the whole right-hand side (contact state, the law,
// derivatives); BM_rhs_hertz/<law> the same under `[contact] patch = "hertz"` (lambda matched on
// the lower pole, docs/contact-models.md); BM_contact_point the contact point alone; BM_law_at_contact/<law> the law alone on
// the contact inputs of those states. BM_rhs_ellipsoid/<law> (and _hertz) is the right-hand side of
// the triaxial ellipsoid of data/scenarios/ellipsoid-case-a.toml (semi-axes 0.2, 0.17, 0.14 m, 2 kg,
// homogeneous: the general shape path, dynamics/shapes/ellipsoid.h) on the same 2001 states (the
// same eps, so the same 1023 in contact): the target is within 1.3x of BM_rhs/<law>
// (docs/benchmarks.md).
// Ratios are only meaningful within one run.

#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "dynamics/body/body.h"
#include "dynamics/body/equations_of_motion.h"
#include "dynamics/contact/hertz_ellipse.h"
#include "dynamics/contact/patch_model.h"
#include "dynamics/body/simulation.h"
#include "friction/registry.h"

namespace frictionlab::bench {
namespace {

using dynamics::StateVector;

dynamics::Body egg_printed() {
  dynamics::BodySpec spec;
  spec.preset = "egg-printed";
  spec.mass = 2.0;
  return dynamics::make_body(spec);
}

const dynamics::PlaneContact kPlane{0.1, 1e7, 9.81};

class StateRecorder final : public dynamics::Observer {
 public:
  void sample(const dynamics::Sample& s) override { states.push_back(s.x); }
  std::vector<StateVector> states;
};

// The states of the first 2 s of case a under the exact law (once per process).
const std::vector<StateVector>& case_a_states() {
  static const std::vector<StateVector> states = [] {
    const auto law = friction::make_law("exact");
    const dynamics::BodyOnPlane sys(egg_printed(), kPlane, *law);
    const StateVector x0 = dynamics::make_state(Eigen::Vector3d::Zero(), {0.0, 0.0, 100.0},
                                                {std::sqrt(1.0 - 0.97 * 0.97), 0.0, 0.97}, -0.3e-4);
    dynamics::RunOptions o;
    o.t_end = 2.0;
    o.output_dt = 1e-3;
    StateRecorder rec;
    (void)dynamics::simulate(sys, x0, o, &rec);
    return rec.states;
  }();
  return states;
}

// The right-hand side of `body` on `plane` with the law `spec`, over the egg's case-a states in turn.
void time_body_rhs(benchmark::State& state, const std::string& spec, const dynamics::Body& body,
                   const dynamics::PlaneContact& plane) {
  const auto law = friction::make_law(spec);
  const dynamics::BodyOnPlane sys(body, plane, *law);
  const auto& xs = case_a_states();
  StateVector d;
  std::size_t i = 0;
  for (auto _ : state) {
    sys(0.0, xs[i], d);
    benchmark::DoNotOptimize(d);
    if (++i == xs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void time_rhs(benchmark::State& state, const std::string& spec, const dynamics::PlaneContact& plane) {
  time_body_rhs(state, spec, egg_printed(), plane);
}

void BM_rhs(benchmark::State& state, const std::string& spec) { time_rhs(state, spec, kPlane); }

dynamics::Body triaxial_ellipsoid() {
  dynamics::BodySpec spec;
  spec.shape = "ellipsoid";
  spec.shape_parameters["semi_axes"] = {0.2, 0.17, 0.14};
  spec.mass = 2.0;
  return dynamics::make_body(spec);
}

dynamics::PlaneContact matched_hertz_plane(const dynamics::Body& body) {
  dynamics::PlaneContact plane = kPlane;
  dynamics::PatchModelSpec spec;
  spec.patch = "hertz";
  spec.lambda = kPlane.lambda;
  dynamics::apply_patch_model(spec, body, plane);
  return plane;
}

void time_ellipsoid_rhs(benchmark::State& state, const std::string& spec, bool hertz) {
  const dynamics::Body body = triaxial_ellipsoid();
  time_body_rhs(state, spec, body, hertz ? matched_hertz_plane(body) : kPlane);
}

void BM_rhs_ellipsoid(benchmark::State& state, const std::string& spec) { time_ellipsoid_rhs(state, spec, false); }
void BM_rhs_ellipsoid_hertz(benchmark::State& state, const std::string& spec) { time_ellipsoid_rhs(state, spec, true); }

// The same plane under Hertz's theory, its modulus matched to kPlane's lambda on the lower pole.
dynamics::PlaneContact hertz_plane() {
  dynamics::PlaneContact plane = kPlane;
  dynamics::PatchModelSpec spec;
  spec.patch = "hertz";
  spec.lambda = kPlane.lambda;
  dynamics::apply_patch_model(spec, egg_printed(), plane);
  return plane;
}

void BM_rhs_hertz(benchmark::State& state, const std::string& spec) { time_rhs(state, spec, hertz_plane()); }

// Hertz's ellipse alone (dynamics/contact/hertz_ellipse.h) at the principal radii of those states.
void BM_hertz_ellipse(benchmark::State& state) {
  const auto law = friction::make_law("exact");
  const dynamics::BodyOnPlane sys(egg_printed(), kPlane, *law);
  std::vector<dynamics::ContactPoint> points;
  for (const auto& x : case_a_states()) points.push_back(sys.geometry().contact_point(dynamics::vertical(x).normalized()));
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(dynamics::hertz_ellipse(points[i].R_meridian, points[i].R_parallel));
    if (++i == points.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_contact_point(benchmark::State& state) {
  const auto law = friction::make_law("exact");
  const dynamics::BodyOnPlane sys(egg_printed(), kPlane, *law);
  std::vector<Eigen::Vector3d> gammas;
  for (const auto& x : case_a_states()) gammas.push_back(dynamics::vertical(x).normalized());
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(sys.geometry().contact_point(gammas[i]));
    if (++i == gammas.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

void BM_law_at_contact(benchmark::State& state, const std::string& spec) {
  const auto law = friction::make_law(spec);
  const dynamics::BodyOnPlane sys(egg_printed(), kPlane, *law);
  std::vector<friction::ContactInput> inputs;
  for (const auto& x : case_a_states()) {
    const dynamics::ContactState c = sys.contact_state(x);
    if (c.N > 0.0) inputs.push_back({c.U, c.Omega, c.a, c.b, c.psi, c.N, kPlane.k});
  }
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(law->evaluate(inputs[i]));
    if (++i == inputs.size()) i = 0;
  }
  state.SetItemsProcessed(state.iterations());
}

const bool registered = [] {
  for (const char* spec : {"exact", "pade-reconstructed", "moller-ellipsoidal"}) {
    benchmark::RegisterBenchmark((std::string("BM_rhs/") + spec).c_str(), BM_rhs, std::string(spec));
    benchmark::RegisterBenchmark((std::string("BM_law_at_contact/") + spec).c_str(), BM_law_at_contact,
                                 std::string(spec));
    benchmark::RegisterBenchmark((std::string("BM_rhs_ellipsoid/") + spec).c_str(), BM_rhs_ellipsoid, std::string(spec));
  }
  benchmark::RegisterBenchmark("BM_rhs_ellipsoid_hertz/exact", BM_rhs_ellipsoid_hertz, std::string("exact"));
  benchmark::RegisterBenchmark("BM_rhs_hertz/exact", BM_rhs_hertz, std::string("exact"));
  benchmark::RegisterBenchmark("BM_contact_point", BM_contact_point);
  benchmark::RegisterBenchmark("BM_hertz_ellipse", BM_hertz_ellipse);
  return true;
}();

}  // namespace
}  // namespace frictionlab::bench

BENCHMARK_MAIN();
