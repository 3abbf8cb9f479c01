#include "friction/support/interrupt_guard.h"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <stdexcept>

namespace frictionlab::support {
namespace interrupt_guard_test {

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

// What a guard with an announcement writes on stderr when `signal` arrives (fd 2 redirected to a file).
std::string announced(const std::string& announcement, int signal) {
  const auto file = std::filesystem::temp_directory_path() /
                    ("frictionlab_interrupt_guard_" + std::to_string(::getpid()));
  std::fflush(stderr);
  const int saved = ::dup(STDERR_FILENO);
  const int fd = ::open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  ::dup2(fd, STDERR_FILENO);
  ::close(fd);
  {
    const InterruptGuard guard(announcement);
    std::raise(signal);
  }
  ::dup2(saved, STDERR_FILENO);
  ::close(saved);
  std::ifstream in(file);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(file);
  return text;
}

// Under mpirun a job gets SIGKILL one second after SIGTERM: the line must be out at the signal.
TEST(SupportInterruptGuardAnnouncement, IsWrittenAtTheFirstSignalWithItsName) {
  EXPECT_EQ(announced("frictionlab: job: stopped by {signal}; runs kept", SIGTERM),
            "frictionlab: job: stopped by SIGTERM; runs kept\n");
  EXPECT_EQ(announced("stopped by {signal}", SIGINT), "stopped by SIGINT\n");
  EXPECT_EQ(announced("no name here", SIGHUP), "no name here\n");
  EXPECT_EQ(announced("", SIGTERM), "") << "no announcement: nothing written";
}

}  // namespace
}  // namespace frictionlab::support
