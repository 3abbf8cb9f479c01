#include "dynamics/core/chatter_watch.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace frictionlab::dynamics {
namespace chatter_watch_test {

// A 5 cm body under 9.81 m/s^2 (dynamics/body/body_scales.h).
BodyScales scales_of(double mass, double size) {
  BodyScales s;
  s.size = size;
  s.mass = mass;
  s.gravity = 9.81;
  s.speed = std::sqrt(9.81 * size);
  s.rate = std::sqrt(9.81 / size);
  s.energy = mass * 9.81 * size;
  return s;
}

// Round thresholds for the synthetic sequences: slip 1e-3 m/s, spin 1e-2 1/s, step 1e-7 s,
// budget 100 steps (25 rebounds).
ChatterRule rule(long budget = 100) {
  ChatterThresholds given;
  given.max_steps = budget;
  given.step = 1e-7;
  RestThresholds rest;
  rest.slip_speed = 1e-3;
  rest.spin = 1e-2;
  const BodyScales s = scales_of(1.0, 0.05);
  return resolve_chatter(given, resolve_rest(rest, s), s);
}

constexpr double kChatterStep = 1e-10;  // s: a chattering step, far below the rule's 1e-7

// Feeds `n` steps of size h from t, the slip U alternating between +x and -x every `period` steps
// (period 0: never; with spin_flips the spin alternates instead), spin Omega; returns the step
// (1-based, of this call) at which the watch fired, or 0.
struct Feed {
  ChatterWatch& watch;
  double t = 0.0;
  long fed = 0;
  ChatterChannel fired = ChatterChannel::none;

  long run(long n, double h, double U, double Omega, long period, bool in_contact = true, bool spin_flips = false) {
    for (long i = 0; i < n; ++i) {
      const double sign = period > 0 && (fed / period) % 2 == 1 ? -1.0 : 1.0;
      ChatterProbe p;
      p.t0 = t;
      p.t1 = t + h;
      p.in_contact = in_contact;
      p.slip = Eigen::Vector3d(spin_flips ? U : sign * U, 0.0, 0.0);
      p.spin = spin_flips ? sign * Omega : Omega;
      t = p.t1;
      ++fed;
      const ChatterChannel c = watch.update(p);
      if (c != ChatterChannel::none) {
        fired = c;
        return i + 1;
      }
    }
    return 0;
  }
};

TEST(DynChatterWatch, DefaultStepIsAFractionOfTheBodysTimeScale) {
  const BodyScales s = scales_of(2.0, 0.265);
  const RestRule rest = resolve_rest({}, s);
  const ChatterRule r = resolve_chatter({}, rest, s);
  EXPECT_DOUBLE_EQ(r.step.value, 3e-6 * std::sqrt(0.265 / 9.81));
  EXPECT_EQ(r.step.key, "run.chatter_step");
  EXPECT_EQ(r.step.unit, "s");
  EXPECT_EQ(r.step.source.rfind("default: ", 0), 0u) << r.step.source;
  EXPECT_NE(r.step.source.find("sqrt(R/g)"), std::string::npos) << r.step.source;
  EXPECT_NE(r.step.source.find("R = 0.265 m"), std::string::npos) << r.step.source;
  EXPECT_EQ(r.max_steps.key, "run.max_chatter_steps");
  EXPECT_EQ(r.max_steps.value, static_cast<double>(kDefaultMaxChatterSteps));
  // The slip and spin bounds are the rest thresholds, as applied.
  EXPECT_EQ(r.slip_speed.key, "run.rest_slip_speed");
  EXPECT_EQ(r.slip_speed.value, rest.slip_speed.value);
  EXPECT_EQ(r.spin.value, rest.spin.value);
  // A body four times as large has a time scale twice as long.
  EXPECT_DOUBLE_EQ(resolve_chatter({}, rest, scales_of(2.0, 4 * 0.265)).step.value, 2.0 * r.step.value);
  ChatterThresholds given;
  given.step = 3e-9;
  const ChatterRule g = resolve_chatter(given, rest, s);
  EXPECT_EQ(g.step.value, 3e-9);
  EXPECT_EQ(g.step.source, "given");
}

TEST(DynChatterWatch, InvalidThresholdsNameTheKey) {
  ChatterThresholds t;
  t.max_steps = -1;
  EXPECT_THROW(t.validate(), std::invalid_argument);
  try {
    t.validate();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("run.max_chatter_steps"), std::string::npos) << e.what();
  }
  for (const double bad : {0.0, -1e-9, std::nan(""), std::numeric_limits<double>::infinity()}) {
    ChatterThresholds s;
    s.step = bad;
    try {
      s.validate();
      ADD_FAILURE() << "run.chatter_step = " << bad << " must be refused";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("run.chatter_step"), std::string::npos) << e.what();
    }
  }
  ChatterThresholds never;
  never.max_steps = 0;
  EXPECT_NO_THROW(never.validate());
}

TEST(DynChatterWatch, ReboundsNeededAreAQuarterOfTheBudgetRoundedUp) {
  EXPECT_EQ(rule(100).rebounds_needed(), 25);
  EXPECT_EQ(rule(1000).rebounds_needed(), 250);
  EXPECT_EQ(rule(1).rebounds_needed(), 1);
  EXPECT_EQ(rule(101).rebounds_needed(), 26);
  EXPECT_EQ(rule(0).rebounds_needed(), 0);
}

TEST(DynChatterWatch, ASlipFlippingEveryStepFiresAtTheBudget) {
  ChatterWatch w(rule(100));
  Feed f{w};
  // The step that lands in the chatter: U has just reached 0 (no reversal yet).
  EXPECT_EQ(f.run(1, kChatterStep, 5e-10, 20.0, 0), 0);
  EXPECT_EQ(f.run(1000, kChatterStep, 5e-10, 20.0, 1), 99);
  EXPECT_EQ(f.fired, ChatterChannel::slip);
  const ChatterEpisode& e = w.episode(ChatterChannel::slip);
  EXPECT_EQ(e.steps, 100);
  EXPECT_EQ(e.rebounds, 99);  // every step but the first flips the slip
  EXPECT_DOUBLE_EQ(e.since, 0.0);
  EXPECT_NEAR(e.min_step, kChatterStep, 1e-9 * kChatterStep);  // t1 - t0 rounds
  EXPECT_DOUBLE_EQ(e.spin, 20.0);
}

TEST(DynChatterWatch, TooFewReversalsDoNotFireUntilTheyAccumulate) {
  // One reversal in 10 steps, the slip's size fixed: the budget of 100 collapsed steps is reached
  // with 9 rebounds; the 25th comes at the 251st step (the slip flips at steps 11, 21, ..., 251).
  ChatterWatch w(rule(100));
  Feed f{w};
  EXPECT_EQ(f.run(1000, kChatterStep, 5e-10, 20.0, 10), 251);
  EXPECT_EQ(w.episode(ChatterChannel::slip).rebounds, 25);
}

TEST(DynChatterWatch, ASawtoothSlipThatNeverReversesFires) {
  // The slip keeps its direction and alternates between 3e-9 and 8e-9 m/s (egg-printed case c
  // under decoupled:r_spin=0): it grows on every other step, half of them rebound.
  ChatterWatch w(rule(100));
  for (int i = 0; i < 1000; ++i) {
    ChatterProbe p;
    p.t0 = i * kChatterStep;
    p.t1 = p.t0 + kChatterStep;
    p.in_contact = true;
    p.slip = Eigen::Vector3d(0.0, i % 2 == 0 ? 3e-9 : 8e-9, 0.0);
    p.spin = 90.0;
    const ChatterChannel c = w.update(p);
    if (c != ChatterChannel::none) {
      EXPECT_EQ(c, ChatterChannel::slip);
      EXPECT_EQ(i + 1, 100);
      EXPECT_EQ(w.episode(c).rebounds, 50);
      return;
    }
  }
  FAIL() << "the sawtooth chatter was not caught";
}

TEST(DynChatterWatch, ASmoothApproachToZeroSlipNeverFires) {
  // A smooth law: the slip shrinks geometrically without ever reversing, with tiny steps.
  ChatterWatch w(rule(100));
  double U = 1e-4;
  for (int i = 0; i < 100000; ++i, U *= 0.999) {
    ChatterProbe p;
    p.t0 = i * kChatterStep;
    p.t1 = p.t0 + kChatterStep;
    p.in_contact = true;
    p.slip = Eigen::Vector3d(U * std::cos(1e-3 * i), U * std::sin(1e-3 * i), 0.0);  // turning slowly
    p.spin = 20.0;
    ASSERT_EQ(w.update(p), ChatterChannel::none) << "step " << i;
  }
}

TEST(DynChatterWatch, EachConditionIsNeeded) {
  const auto fires = [](double h, double U, double Omega, bool in_contact) {
    ChatterWatch w(rule(100));
    Feed f{w};
    return f.run(1000, h, U, Omega, 1, in_contact) > 0;
  };
  EXPECT_TRUE(fires(kChatterStep, 5e-10, 20.0, true));
  EXPECT_FALSE(fires(2e-7, 5e-10, 20.0, true)) << "steps above run.chatter_step";
  EXPECT_FALSE(fires(kChatterStep, 2e-3, 20.0, true)) << "slip above run.rest_slip_speed";
  EXPECT_FALSE(fires(kChatterStep, 5e-10, 5e-3, true)) << "both small: the stagnation region's";
  EXPECT_FALSE(fires(kChatterStep, 5e-10, 20.0, false)) << "out of contact";
}

TEST(DynChatterWatch, ABreakInTheRunStartsTheCountAgain) {
  ChatterWatch w(rule(100));
  Feed f{w};
  EXPECT_EQ(f.run(90, kChatterStep, 5e-10, 20.0, 1), 0);
  EXPECT_EQ(f.run(1, 1e-3, 5e-10, 20.0, 1), 0);  // one ordinary step
  EXPECT_EQ(w.episode(ChatterChannel::slip).steps, 0);
  const double restart = f.t;
  EXPECT_EQ(f.run(1000, kChatterStep, 5e-10, 20.0, 1), 100);
  EXPECT_DOUBLE_EQ(w.episode(ChatterChannel::slip).since, restart);
}

TEST(DynChatterWatch, ASpinFlippingWhileItSlipsFiresOnTheSpinChannel) {
  ChatterWatch w(rule(100));
  Feed f{w};
  EXPECT_EQ(f.run(1000, kChatterStep, 0.3, 1e-9, 1, true, true), 100);
  EXPECT_EQ(f.fired, ChatterChannel::spin);
  EXPECT_EQ(w.episode(ChatterChannel::spin).rebounds, 99);
  EXPECT_EQ(w.episode(ChatterChannel::slip).steps, 0);
}

TEST(DynChatterWatch, ABudgetOfZeroNeverFires) {
  ChatterWatch w(rule(0));
  Feed f{w};
  EXPECT_EQ(f.run(10000, kChatterStep, 5e-10, 20.0, 1), 0);
}

TEST(DynChatterWatch, TheMessageSaysWhatChatteredSinceWhenAndWhatToDo) {
  const ChatterRule r = rule(100);
  ChatterWatch w(r);
  Feed f{w};
  f.t = 0.25;
  ASSERT_GT(f.run(1000, kChatterStep, 5e-10, 20.0, 1), 0);
  const std::string m = chatter_message(w.episode(ChatterChannel::slip), r, "decoupled");
  for (const char* part : {"the slip chattered", "since t = 0.25 s", "100 accepted steps", "run.rest_slip_speed",
                           "grew again or reversed its direction on 99", "'decoupled' is discontinuous at U = 0",
                           "not held there",
                           "run.max_chatter_steps = 0"})
    EXPECT_NE(m.find(part), std::string::npos) << part << " in: " << m;
  EXPECT_NE(chatter_rule_text(ChatterChannel::slip).find("run.chatter_step"), std::string::npos);
  EXPECT_NE(chatter_rule_text(ChatterChannel::spin).find("|Omega| < run.rest_spin"), std::string::npos);
}

}  // namespace
}  // namespace frictionlab::dynamics
