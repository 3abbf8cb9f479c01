#include "friction/support/interrupt_guard.h"

#include <array>
#include <cerrno>
#include <csignal>
#include <stdexcept>
#include <system_error>

namespace frictionlab::support {
namespace {

constexpr std::array<int, 3> kSignals = {SIGINT, SIGTERM, SIGHUP};

// Lock-free atomics and sig_atomic_t are what a signal handler may touch.
std::atomic<bool> g_flag{false};
volatile std::sig_atomic_t g_signal = 0;
std::atomic<bool> g_alive{false};
std::array<struct sigaction, kSignals.size()> g_previous{};

static_assert(std::atomic<bool>::is_always_lock_free);

extern "C" void on_interrupt(int sig) {
  if (g_flag.load()) {
    // Second signal: the default action (usually termination), as if no guard were there.
    std::signal(sig, SIG_DFL);
    std::raise(sig);
    return;
  }
  g_signal = sig;
  g_flag.store(true);
}

}  // namespace

InterruptGuard::InterruptGuard() {
  if (g_alive.exchange(true)) throw std::logic_error("InterruptGuard: another guard is alive");
  g_flag.store(false);
  g_signal = 0;
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;  // interrupted reads and writes resume; the job polls the flag
  for (std::size_t i = 0; i < kSignals.size(); ++i) {
    if (sigaction(kSignals[i], &action, &g_previous[i]) != 0) {
      const int error_number = errno;
      for (std::size_t j = 0; j < i; ++j) sigaction(kSignals[j], &g_previous[j], nullptr);
      g_alive.store(false);
      throw std::system_error(error_number, std::generic_category(), "InterruptGuard: sigaction");
    }
  }
}

InterruptGuard::~InterruptGuard() {
  for (std::size_t i = 0; i < kSignals.size(); ++i) sigaction(kSignals[i], &g_previous[i], nullptr);
  g_alive.store(false);
}

const std::atomic<bool>& InterruptGuard::flag() const { return g_flag; }

int InterruptGuard::signal_number() const { return static_cast<int>(g_signal); }

}  // namespace frictionlab::support
