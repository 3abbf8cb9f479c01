// `exact` makes no heap allocation per evaluation: counted through the global
// operator new, over the benchmark's input set and the special cases.

#include <gtest/gtest.h>

#include "bench/allocation_counter.h"
#include "bench/law_input_set.h"
#include "friction/exact_law.h"

namespace frictionlab::friction {
namespace exact_law_allocation_test {

TEST(ExactLawAllocation, NoHeapAllocationPerEvaluation) {
  const ExactLaw law;
  auto inputs = bench::law_input_set(512);
  inputs.push_back({0.0, 3.0, 1.0, 0.3, 0.2, 1.0, 1.0});    // pure spin
  inputs.push_back({2.0, 0.0, 1.0, 0.3, 0.2, 1.0, 1.0});    // pure sliding
  inputs.push_back({1.0, 1.0, 1.0, 0.01, 0.0, 1.0, 1.0});   // slender, centre on the rim
  inputs.push_back({1e9, 1e-3, 1.0, 0.5, 0.7, 1.0, 1.0});   // fast slip expansion
  (void)law.evaluate(inputs.front());  // first call may initialise static tables
  const long long before = bench::g_allocations.load();
  double sink = 0.0;
  for (const auto& in : inputs) sink += law.evaluate(in).F1;
  EXPECT_EQ(bench::g_allocations.load() - before, 0);
  EXPECT_TRUE(std::isfinite(sink));
}

TEST(ExactLawAllocation, TheCounterSeesAllocations) {
  // The check above can fail: an allocation is counted.
  const long long before = bench::g_allocations.load();
  void* p = ::operator new(32);  // a direct call: new-expressions may be elided
  ::operator delete(p);
  EXPECT_GT(bench::g_allocations.load() - before, 0);
}

}  // namespace
}  // namespace frictionlab::friction
