#include "dynamics/core/pole_watch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dynamics/body/equations_of_motion.h"
#include "friction/pade_printed_law.h"
#include "friction/registry.h"
#include "tests/dynamics/test_support.h"

// Counts heap allocations in this test program (the watch runs inside the right-hand side).
#include "bench/allocation_counter.h"
using frictionlab::bench::g_allocations;

namespace frictionlab::dynamics {
namespace pole_watch_test {

// The body's map of its contact to the watch's shape coordinates (BodyOnPlane::pole_point); a
// point is itself.
PoleWatch::Point pt(const ContactState& c) { return BodyOnPlane::pole_point(c); }
PoleWatch::Point pt(const PoleWatch::Point& p) { return p; }

constexpr double kMu = 0.9, kPsi = 0.3, kA = 0.01, kOmega = 10.0;

// A contact of the printed law's shape with slip ratio s = U/(a |Omega|).
ContactState in_contact(double s, double psi = kPsi) {
  ContactState c;
  c.in_contact = true;
  c.a = kA;
  c.b = kMu * kA;
  c.psi = psi;
  c.Omega = kOmega;
  c.U = s * kA * kOmega;
  c.N = 10.0;
  return c;
}

// The same body out of contact: the patch has shrunk to nothing (s = inf); its shape mu comes from
// the principal radii, b/a = sqrt(R_min/R_max).
ContactState out_of_contact() {
  ContactState c = in_contact(1.0);
  c.in_contact = false;
  c.a = c.b = c.N = 0.0;
  c.point.R_meridian = 0.3;
  c.point.R_parallel = 0.3 * kMu * kMu;
  return c;
}

// The positive root of the printed F2 denominator s^2 + a3 s + a4 (eq. (8), alpha = a, a4 < 0 for
// 0 < psi < pi/2), from eq. (9)'s coefficients.
double f2_root() {
  const auto k = friction::pade_printed_coefficients(kMu, kPsi);
  EXPECT_LT(k.a4, 0.0);
  return 0.5 * (-k.a3 + std::sqrt(k.a3 * k.a3 - 4.0 * k.a4));
}

TEST(DynPoleWatch, ALawWithoutPolesIsNotWatched) {
  const auto law = friction::make_law("exact");
  PoleWatch w(*law, 0.1);
  EXPECT_FALSE(w.active());
  w.set_reference(pt(in_contact(1.0)));
  EXPECT_EQ(w.crossing(pt(in_contact(1e6))), -1);
}

TEST(DynPoleWatch, MapsAStateToItsShape) {
  const auto law = friction::make_law("pade-printed");
  const PoleWatch w(*law, 0.1);
  const PoleWatch::Point p = pt(in_contact(3.0));
  EXPECT_NEAR(p.t, 1.0 / (1.0 + 3.0), 1e-15);
  EXPECT_NEAR(p.mu, kMu, 1e-15);
  EXPECT_EQ(p.psi, kPsi);
  const PoleWatch::Point q = pt(out_of_contact());
  EXPECT_EQ(q.t, 0.0);
  EXPECT_NEAR(q.mu, kMu, 1e-15);
  ContactState no_spin = in_contact(3.0);
  no_spin.Omega = 0.0;
  EXPECT_EQ(pt(no_spin).t, 0.0);  // s = inf
  // The denominators at a point are the law's at any contact of that shape.
  const auto d = w.denominators(p);
  const friction::ContactInput in{3.0 * 0.02 * 7.0, 7.0, 0.02, 0.02 * kMu, kPsi, 3.0, 0.1};
  const friction::PoleDenominators e = law->pole_denominators(in);
  EXPECT_NEAR(d[0], e.F1, 1e-12 * std::abs(e.F1));
  EXPECT_NEAR(d[1], e.F2, 1e-12 * std::abs(e.F2));
  EXPECT_NEAR(d[2], e.M, 1e-12 * std::abs(e.M));
}

TEST(DynPoleWatch, FindsTheRealPoleOfThePrintedF2) {
  const auto law = friction::make_law("pade-printed");
  PoleWatch w(*law, 0.1);
  ASSERT_TRUE(w.active());
  const double s_r = f2_root();
  w.set_reference(pt(in_contact(0.9 * s_r)));
  EXPECT_EQ(w.crossing(pt(in_contact(0.99 * s_r))), -1);
  EXPECT_EQ(w.crossing(pt(in_contact(1.01 * s_r))), 1);  // F2
  EXPECT_EQ(w.crossing(pt(in_contact(s_r * (1.0 + 1e-12)))), 1);
  w.set_reference(pt(in_contact(1.1 * s_r)));  // and from the other side
  EXPECT_EQ(w.crossing(pt(in_contact(0.9 * s_r))), 1);
  EXPECT_EQ(w.crossing(pt(in_contact(1e9))), -1);
}

TEST(DynPoleWatch, LandingAndLiftingOffWithSlipCrossTheRealPole) {
  // Out of contact the patch has no size: s = inf, where the F2 denominator is positive.
  const auto law = friction::make_law("pade-printed");
  PoleWatch w(*law, 0.1);
  const double s_r = f2_root();
  w.set_reference(pt(out_of_contact()));
  EXPECT_EQ(w.crossing(pt(in_contact(2.0 * s_r))), -1);
  EXPECT_EQ(w.crossing(pt(in_contact(0.5 * s_r))), 1);
  w.set_reference(pt(in_contact(0.5 * s_r)));
  EXPECT_EQ(w.crossing(pt(out_of_contact())), 1);
}

TEST(DynPoleWatch, ASignChangeThroughInfinityIsNoPole) {
  // As psi passes 0 (mod pi), d6 = (1 - mu^(1/4)) sin 2psi changes sign and a4 = -8/(3 mu^(3/4) pi
  // d6) jumps from -inf to +inf: the F2 denominator changes sign, but F2 goes smoothly through 0.
  const auto law = friction::make_law("pade-printed");
  PoleWatch w(*law, 0.1);
  const ContactState before = in_contact(5.0, 0.01), after = in_contact(5.0, std::numbers::pi - 0.01);
  const auto p0 = w.denominators(pt(before)), p1 = w.denominators(pt(after));
  ASSERT_LT(p0[1], 0.0);
  ASSERT_GT(p1[1], 0.0);
  w.set_reference(pt(before));
  EXPECT_EQ(w.crossing(pt(after)), -1);
  // The same at psi = pi/2, where sin 2psi changes sign too.
  w.set_reference(pt(in_contact(5.0, std::numbers::pi / 2 - 0.01)));
  EXPECT_EQ(w.crossing(pt(in_contact(5.0, std::numbers::pi / 2 + 0.01))), -1);
}

TEST(DynPoleWatch, AStateOnThePoleLetsNoStepLeaveIt) {
  // An accepted state whose denominator is exactly 0 lies on the pole: no move from it may be
  // accepted, on either side, or the run would step across the pole unseen.
  const testing::DeclaredPoleTestLaw law(3.0, true);  // F2's denominator s - 3; s = 3 is t = 1/4
  PoleWatch w(law, 0.1);
  const PoleWatch::Point on = PoleWatch::patch_point(3.0, 1.0, 1.0, 1.0, 0.0);
  ASSERT_EQ(w.denominators(on)[1], 0.0);
  w.set_reference(pt(on));
  EXPECT_EQ(w.crossing(pt(PoleWatch::patch_point(3.0 + 1e-12, 1.0, 1.0, 1.0, 0.0))), 1);
  EXPECT_EQ(w.crossing(pt(PoleWatch::patch_point(3.0 - 1e-12, 1.0, 1.0, 1.0, 0.0))), 1);
  // Off the pole nothing changes: the same side is no crossing.
  w.set_reference(pt(PoleWatch::patch_point(2.5, 1.0, 1.0, 1.0, 0.0)));
  EXPECT_EQ(w.crossing(pt(PoleWatch::patch_point(2.9, 1.0, 1.0, 1.0, 0.0))), -1);
  EXPECT_EQ(w.crossing(pt(PoleWatch::patch_point(3.1, 1.0, 1.0, 1.0, 0.0))), 1);
}

TEST(DynPoleWatch, ACrossingAtRoundingLevelIsAPole) {
  // The integrator closes in on a pole until the denominator at both ends of a step is at rounding
  // level (~4e-16 here, s = (1 - t)/t); the bisection can then no longer show |D| falling inside the
  // segment. Such a sign change must count as a pole: only |D| rising inside it (a passage through
  // infinity) is none. Seen in a puck run stepping across a declared pole of a linear denominator.
  const testing::DeclaredPoleTestLaw law(2.0, true);
  PoleWatch w(law, 0.1);
  int sign_changes = 0;
  for (const double a : {0.03, 0.01, 1.0})
    for (const double omega : {14.2088087729, 3.7, 100.0})
      for (int i = 1; i <= 20; ++i)
        for (int j = 1; j <= 20; ++j) {
          const double aw = a * omega;
          const PoleWatch::Point before = PoleWatch::patch_point(aw * (2.0 - i * 2.2e-16), omega, a, a, 0.0);
          const PoleWatch::Point after = PoleWatch::patch_point(aw * (2.0 + j * 2.2e-16), omega, a, a, 0.0);
          if (!(w.denominators(before)[1] < 0.0 && w.denominators(after)[1] > 0.0)) continue;
          ++sign_changes;
          w.set_reference(pt(before));
          EXPECT_EQ(w.crossing(pt(after)), 1) << a << " " << omega << " " << i << " " << j;
        }
  EXPECT_GT(sign_changes, 100);
}

TEST(DynPoleWatch, WatchingMakesNoHeapAllocation) {
  const auto law = friction::make_law("pade-printed");
  PoleWatch w(*law, 0.1);
  const double s_r = f2_root();
  w.set_reference(pt(in_contact(0.9 * s_r)));
  (void)w.crossing(pt(in_contact(2.0)));  // warm-up
  const long long before = g_allocations.load();
  int found = 0;
  for (int i = 0; i < 100; ++i) {
    found += w.crossing(pt(in_contact(0.5 * s_r + 0.01 * i))) >= 0;
    found += w.crossing(pt(in_contact(1.5 * s_r))) >= 0;  // a sign change, classified by bisection
    found += w.crossing(pt(in_contact(5.0, std::numbers::pi - 0.01))) >= 0;
  }
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_EQ(found, 100);
}

}  // namespace
}  // namespace frictionlab::dynamics
