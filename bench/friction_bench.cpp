// Cost of each friction law per evaluation, on one fixed seeded input set (bench/law_input_set.h),
// with each law's largest error against the reference law (`exact`) on that set as counters. Every
// spec of list_law_specs() is timed: `BM_law/exact:pressure=uniform` too (its counters are then the
// difference between the pressure models, not an error).
//
//   build/bench/friction_bench                       # all laws
//   build/bench/friction_bench --benchmark_filter='BM_law/(exact|pade-printed)$'
//   build/bench/friction_bench --benchmark_min_time=0   # one iteration each: a smoke run of seconds
//
// One iteration = one evaluation, cycling through the set, so the reported time is the mean cost
// per evaluation over the contacts evaluated. The library chooses the iteration count from
// --benchmark_min_time (default 0.5 s) for every law, the slow ones too. Ratios between laws are
// only meaningful within one run.
// `BM_law/<spec>` evaluates inputs that carry the patch angle psi, as a caller holding an angle
// does (the command line, Python): the law forms cos psi and sin psi (friction::PatchAngle::cos_sin)
// in each evaluation, as it always did. `BM_law_direction/<spec>` evaluates the same contacts with
// the major axis given as its direction (cos psi, sin psi), as the dynamics hands it over.
// `BM_law_batch/<spec>` evaluates the whole set in one call (FrictionLaw::evaluate of spans, the
// law's own batch evaluation), the contacts the law rejects (a pole of pade-printed) left out; one
// iteration is one batch, items_per_second counts contacts, so its time per item compares with
// BM_law's time per evaluation.
//
// `BM_exact_table_build/<pressure>` times what the first evaluation of `exact-table` with that
// pressure costs once per process: building its table from `exact` (friction/exact_table.h),
// counters exact_evaluations (calls of exact) and bytes (of coefficients).
//
// `BM_fit_standalone/forces` times what an engine pays for `fit` when it keeps each contact's
// geometry (frictionlab_fit::make_geometry, once per patch shape) and has the patch axes as a
// direction: frictionlab_fit::evaluate of friction/standalone/fit_law.h on the same contacts;
// `BM_fit_standalone/geometry` times make_geometry alone. Compare with BM_law_direction/<spec>.
//
// Counters (units in the names; kN means k times N, the friction coefficient times the normal
// force, not kilonewtons): max_err_F1_kN, max_err_F2_kN (largest |law - exact| of F1, F2 divided by
// k N), max_err_M_kNa (of M divided by k N a), allocs_per_eval (calls of operator new per
// evaluation), inputs (contacts in the set the law cycles through).

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/allocation_counter.h"
#include "bench/law_input_set.h"
#include "friction/exact_table.h"
#include "friction/pressure.h"
#include "friction/registry.h"
#include "friction/reference_laws.h"
#include "friction/standalone/fit_law.h"

namespace frictionlab::bench {
namespace {

// A law the registry marks slow (milliseconds per call) is timed, and checked, on a prefix of the set.
constexpr std::size_t kSlowLawSubset = 64;

struct MaxErrors {
  double F1 = 0.0, F2 = 0.0, M = 0.0;
};

// A law's errors, computed the first time one of its benchmarks runs (never for a law the filter
// leaves out: for a slow law they cost ~1 s) and shared by its two benchmarks.
struct LazyErrors {
  std::shared_ptr<friction::FrictionLaw> law;
  std::vector<friction::ContactInput> set;
  std::optional<MaxErrors> errors;
};

// Largest |law - reference| over `set`, per kN (forces) and kNa (moment); +inf if any output is not
// finite or the law rejects the input (e.g. on a real pole of the printed F2).
MaxErrors max_errors(const friction::FrictionLaw& law, const friction::FrictionLaw& reference,
                     const std::vector<friction::ContactInput>& set) {
  MaxErrors e;
  const auto worst = [](double& m, double x, double ref) {
    const double d = std::abs(x - ref);
    m = std::isfinite(x) ? std::max(m, d) : std::numeric_limits<double>::infinity();
  };
  constexpr double inf = std::numeric_limits<double>::infinity();
  for (const auto& in : set) {
    friction::FrictionForces f{inf, inf, inf};
    try {
      f = law.evaluate(in);
    } catch (const std::invalid_argument&) {
    }
    const auto g = reference.evaluate(in);
    const double kN = in.k * in.N;
    worst(e.F1, f.F1 / kN, g.F1 / kN);
    worst(e.F2, f.F2 / kN, g.F2 / kN);
    worst(e.M, f.M / (kN * in.a), g.M / (kN * in.a));
  }
  return e;
}

// Registers BM_law/<spec> (the inputs as given: angles) or BM_law_direction/<spec> (the same
// inputs with psi as the direction (cos psi, sin psi), formed here, before the timing).
void register_timing(bool from_angle, const std::string& spec, std::shared_ptr<friction::FrictionLaw> law,
                     const std::vector<friction::ContactInput>& inputs, std::shared_ptr<LazyErrors> lazy) {
  auto set = std::make_shared<std::vector<friction::ContactInput>>(inputs);
  if (!from_angle) {
    for (auto& in : *set) {
      const auto [c, s] = in.psi.cos_sin();
      in.psi = friction::PatchAngle::from_direction(c, s);
    }
  }
  const std::string name = (from_angle ? "BM_law/" : "BM_law_direction/") + spec;
  benchmark::RegisterBenchmark(name.c_str(), [law, set, lazy](benchmark::State& state) {
    if (!lazy->errors) lazy->errors = max_errors(*lazy->law, *friction::make_reference_law(), lazy->set);
    const MaxErrors err = *lazy->errors;
    std::size_t i = 0;
    const long long allocations_before = g_allocations.load();
    for (auto _ : state) {
      try {
        benchmark::DoNotOptimize(law->evaluate((*set)[i]));
      } catch (const std::invalid_argument&) {  // a pole of the printed law: not a cost to time
      }
      if (++i == set->size()) i = 0;
    }
    const long long allocations = g_allocations.load() - allocations_before;
    state.SetItemsProcessed(state.iterations());
    state.counters["allocs_per_eval"] =
        static_cast<double>(allocations) / static_cast<double>(state.iterations());
    state.counters["inputs"] = static_cast<double>(set->size());
    state.counters["max_err_F1_kN"] = err.F1;
    state.counters["max_err_F2_kN"] = err.F2;
    state.counters["max_err_M_kNa"] = err.M;
  });
}

// Registers BM_law_batch/<spec>: the set, without the contacts the law rejects (found at its first
// run, never for a law the filter leaves out), in one call per iteration.
void register_batch_timing(const std::string& spec, std::shared_ptr<friction::FrictionLaw> law,
                           const std::vector<friction::ContactInput>& inputs, std::shared_ptr<LazyErrors> lazy) {
  auto set = std::make_shared<std::vector<friction::ContactInput>>();
  auto all = std::make_shared<std::vector<friction::ContactInput>>(inputs);
  benchmark::RegisterBenchmark(("BM_law_batch/" + spec).c_str(), [law, set, all, lazy](benchmark::State& state) {
    if (!lazy->errors) lazy->errors = max_errors(*lazy->law, *friction::make_reference_law(), lazy->set);
    if (set->empty()) {
      for (const auto& in : *all) {
        try {
          (void)law->evaluate(in);
          set->push_back(in);
        } catch (const std::invalid_argument&) {
        }
      }
    }
    std::vector<friction::FrictionForces> out(set->size());
    const long long allocations_before = g_allocations.load();
    for (auto _ : state) {
      law->evaluate(std::span<const friction::ContactInput>(*set), std::span<friction::FrictionForces>(out));
      benchmark::DoNotOptimize(out.data());
      benchmark::ClobberMemory();
    }
    const long long allocations = g_allocations.load() - allocations_before;
    const auto items = static_cast<double>(state.iterations()) * static_cast<double>(set->size());
    state.SetItemsProcessed(static_cast<std::int64_t>(items));
    state.counters["allocs_per_eval"] = static_cast<double>(allocations) / items;
    state.counters["inputs"] = static_cast<double>(set->size());
  });
}

void register_law(const friction::LawInfo& info, const std::vector<friction::ContactInput>& full) {
  const bool slow = info.slow;
  const std::vector<friction::ContactInput> set(
      full.begin(), full.begin() + static_cast<std::ptrdiff_t>(slow ? kSlowLawSubset : full.size()));
  std::shared_ptr<friction::FrictionLaw> law = friction::make_law(info.spec);
  auto lazy = std::make_shared<LazyErrors>(LazyErrors{law, set, std::nullopt});
  register_timing(true, info.spec, law, set, lazy);
  register_timing(false, info.spec, law, set, lazy);
  register_batch_timing(info.spec, law, set, lazy);
}

// The table of exact-table for one pressure, built from exact as at its first evaluation.
void register_table_build(friction::Pressure pressure) {
  const std::string name = "BM_exact_table_build/" + std::string(friction::pressure_name(pressure));
  benchmark::RegisterBenchmark(name.c_str(), [pressure](benchmark::State& state) {
    long evaluations = 0;
    std::size_t bytes = 0;
    for (auto _ : state) {
      const friction::ExactTable table(pressure);
      evaluations = table.exact_evaluations();
      bytes = table.bytes();
      benchmark::DoNotOptimize(bytes);
    }
    state.counters["exact_evaluations"] = static_cast<double>(evaluations);
    state.counters["bytes"] = static_cast<double>(bytes);
  })->Unit(benchmark::kMillisecond);
}

// The standalone header of `fit` as an engine calls it: the geometry per contact kept, the axes
// as a direction.
void register_fit_standalone(const std::vector<friction::ContactInput>& full) {
  struct Contact {
    frictionlab_fit::Geometry geometry;
    double U, Omega, a, c, s, N, k;
  };
  auto contacts = std::make_shared<std::vector<Contact>>();
  for (const friction::ContactInput& in : full) {
    const friction::PatchAngle::CosSin axis = in.psi.cos_sin();
    contacts->push_back({frictionlab_fit::make_geometry(in.b / in.a, frictionlab_fit::Pressure::hertz), in.U, in.Omega,
                         in.a, axis.c, axis.s, in.N, in.k});
  }
  benchmark::RegisterBenchmark("BM_fit_standalone/forces", [contacts](benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
      const Contact& c = (*contacts)[i];
      benchmark::DoNotOptimize(frictionlab_fit::evaluate(c.geometry, c.U, c.Omega, c.a, c.c, c.s, c.N, c.k));
      if (++i == contacts->size()) i = 0;
    }
    state.counters["inputs"] = static_cast<double>(contacts->size());
  });
  auto ratios = std::make_shared<std::vector<double>>();
  for (const friction::ContactInput& in : full) ratios->push_back(in.b / in.a);
  benchmark::RegisterBenchmark("BM_fit_standalone/geometry", [ratios](benchmark::State& state) {
    std::size_t i = 0;
    for (auto _ : state) {
      benchmark::DoNotOptimize(frictionlab_fit::make_geometry((*ratios)[i], frictionlab_fit::Pressure::hertz));
      if (++i == ratios->size()) i = 0;
    }
    state.counters["inputs"] = static_cast<double>(ratios->size());
  });
}

}  // namespace
}  // namespace frictionlab::bench

int main(int argc, char** argv) {
  frictionlab::friction::register_reference_laws();  // exact-reference (GSL) is timed too
  const auto set = frictionlab::bench::law_input_set();
  // Every law, and every variant of its choice parameters (e.g. each pressure model of `exact`).
  for (const auto& spec : frictionlab::friction::list_law_specs()) {
    frictionlab::bench::register_law(frictionlab::friction::law_info(spec), set);
  }
  for (const auto& pressure : frictionlab::friction::pressure_names()) {
    frictionlab::bench::register_table_build(frictionlab::friction::parse_pressure(pressure));
  }
  frictionlab::bench::register_fit_standalone(set);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
