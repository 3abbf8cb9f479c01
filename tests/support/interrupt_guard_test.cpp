#include "friction/support/interrupt_guard.h"

#include <gtest/gtest.h>

#include <csignal>
#include <stdexcept>

namespace frictionlab::support {
namespace {

extern "C" void marker_handler(int) {}

class SupportInterruptGuard : public ::testing::TestWithParam<int> {};

TEST_P(SupportInterruptGuard, ASignalRaisesTheFlagInsteadOfEndingTheProcess) {
  const InterruptGuard guard;
  EXPECT_FALSE(guard.interrupted());
  EXPECT_EQ(guard.signal_number(), 0);
  std::raise(GetParam());
  EXPECT_TRUE(guard.interrupted());
  EXPECT_TRUE(guard.flag().load());
  EXPECT_EQ(guard.signal_number(), GetParam());
}

TEST_P(SupportInterruptGuard, RestoresThePreviousHandler) {
  struct sigaction mine {};
  mine.sa_handler = marker_handler;
  sigemptyset(&mine.sa_mask);
  struct sigaction before {};
  ASSERT_EQ(sigaction(GetParam(), &mine, &before), 0);
  {
    const InterruptGuard guard;
    struct sigaction during {};
    sigaction(GetParam(), nullptr, &during);
    EXPECT_NE(during.sa_handler, &marker_handler);
  }
  struct sigaction after {};
  sigaction(GetParam(), nullptr, &after);
  EXPECT_EQ(after.sa_handler, &marker_handler);
  sigaction(GetParam(), &before, nullptr);
}

TEST_P(SupportInterruptGuard, ASecondSignalEndsTheProcess) {
  GTEST_FLAG_SET(death_test_style, "threadsafe");
  EXPECT_EXIT(
      {
        const InterruptGuard guard;
        std::raise(GetParam());
        std::raise(GetParam());
        std::exit(0);
      },
      ::testing::KilledBySignal(GetParam()), "");
}

INSTANTIATE_TEST_SUITE_P(Signals, SupportInterruptGuard, ::testing::Values(SIGINT, SIGTERM, SIGHUP),
                         [](const auto& p) {
                           return p.param == SIGINT ? "SIGINT" : p.param == SIGTERM ? "SIGTERM" : "SIGHUP";
                         });

TEST(SupportInterruptGuardLifetime, OneGuardAtATime) {
  const InterruptGuard first;
  EXPECT_THROW(InterruptGuard second, std::logic_error);
}

TEST(SupportInterruptGuardLifetime, EachGuardStartsLowered) {
  {
    const InterruptGuard first;
    std::raise(SIGHUP);
    ASSERT_TRUE(first.interrupted());
  }
  const InterruptGuard second;
  EXPECT_FALSE(second.interrupted());
}

}  // namespace
}  // namespace frictionlab::support
