// friction_bench (bench/friction_bench.cpp) run briefly, as docs/benchmarks.md says a short run
// is made: a filter and --benchmark_min_time. No time is asserted (speed lives in bench/): only
// which benchmarks ran, how many iterations the library chose, and the counters they report.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <string>

#include <nlohmann/json.hpp>

namespace frictionlab {
namespace friction_bench_test {

// Runs friction_bench with `args` (shell words) and returns its JSON report (stdout), or a
// discarded value if it failed.
nlohmann::json run_bench(const std::string& args) {
  const std::string cmd = std::string(FRICTION_BENCH_EXE) + " " + args + " --benchmark_format=json 2>/dev/null";
  FILE* pipe = ::popen(cmd.c_str(), "r");
  if (!pipe) return nlohmann::json::value_t::discarded;
  std::string out;
  std::array<char, 4096> buf{};
  for (std::size_t n; (n = std::fread(buf.data(), 1, buf.size(), pipe)) > 0;) out.append(buf.data(), n);
  const int status = ::pclose(pipe);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return nlohmann::json::value_t::discarded;
  return nlohmann::json::parse(out, nullptr, false);
}

// At --benchmark_min_time=0 the library accepts its first trial, one iteration: the slow law
// (~10 ms a call) honours the flag like every other law instead of a fixed 128 iterations.
// The filter also admits the name the fixed count used to add ("/iterations:128").
TEST(FrictionBench, TheSlowLawHonoursTheMinimumTime) {
  const auto report = run_bench("--benchmark_filter='^BM_law/exact-reference($|/)' --benchmark_min_time=0");
  ASSERT_FALSE(report.is_discarded());
  ASSERT_EQ(report["benchmarks"].size(), 1u) << report.dump(1);
  const auto& b = report["benchmarks"][0];
  EXPECT_EQ(b["name"], "BM_law/exact-reference");
  EXPECT_EQ(b["iterations"], 1) << b.dump(1);
}

// The counters carry their unit in their name: errors per kN (k times N, not kilonewtons) and per
// kNa. exact-reference is the independent quadrature of exact, accurate to 1e-10 of kN and kNa on
// b/a >= 0.01 (README): its counters are the two methods' agreement.
TEST(FrictionBench, TheCountersNameTheirUnits) {
  constexpr double kReferenceAccuracy = 1e-10;  // of kN, kNa (exact-reference's documented accuracy)
  const auto report = run_bench("--benchmark_filter='^BM_law/exact-reference($|/)' --benchmark_min_time=0");
  ASSERT_FALSE(report.is_discarded());
  ASSERT_EQ(report["benchmarks"].size(), 1u);
  const auto& b = report["benchmarks"][0];
  for (const char* name : {"max_err_F1_kN", "max_err_F2_kN", "max_err_M_kNa"}) {
    ASSERT_TRUE(b.contains(name)) << name << " in " << b.dump(1);
    EXPECT_LT(b[name].get<double>(), kReferenceAccuracy) << name;
  }
  for (const char* old : {"max_err_F1", "max_err_F2", "max_err_M"}) EXPECT_FALSE(b.contains(old)) << old;
  EXPECT_EQ(b["allocs_per_eval"], 0.0);
  EXPECT_EQ(b["inputs"], 64.0);
}

// A filter runs only what it names: one law, both of its benchmarks at one iteration each.
TEST(FrictionBench, AFilterRunsOnlyTheNamedLaw) {
  const auto report = run_bench("--benchmark_filter='^BM_law(_direction)?/pade-printed$' --benchmark_min_time=0");
  ASSERT_FALSE(report.is_discarded());
  ASSERT_EQ(report["benchmarks"].size(), 2u) << report.dump(1);
  EXPECT_EQ(report["benchmarks"][0]["name"], "BM_law/pade-printed");
  EXPECT_EQ(report["benchmarks"][1]["name"], "BM_law_direction/pade-printed");
  for (const auto& b : report["benchmarks"]) EXPECT_EQ(b["iterations"], 1);
}

}  // namespace
}  // namespace frictionlab
