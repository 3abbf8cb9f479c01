#include "friction/support/interrupt_guard.h"

#include <unistd.h>

#include <algorithm>
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
// The announcement, split at "{signal}" (set before the handlers are installed; read only by them).
constexpr std::size_t kAnnouncementBytes = 480;
std::array<char, kAnnouncementBytes> g_before{};
std::array<char, kAnnouncementBytes> g_after{};
std::size_t g_before_size = 0;
std::size_t g_after_size = 0;
bool g_announce = false;
bool g_announce_name = false;  // the announcement has "{signal}"

std::size_t copy_into(std::array<char, kAnnouncementBytes>& to, std::string_view from) {
  const std::size_t n = std::min(from.size(), to.size());
  std::copy_n(from.begin(), n, to.begin());
  return n;
}

// Only async-signal-safe calls: copies by hand into a local buffer, one write(2).
void announce(int sig) {
  const char* name = InterruptGuard::signal_name(sig);
  char line[2 * kAnnouncementBytes + 32];
  std::size_t n = 0;
  for (std::size_t i = 0; i < g_before_size; ++i) line[n++] = g_before[i];
  for (const char* c = name; g_announce_name && *c; ++c) line[n++] = *c;
  for (std::size_t i = 0; i < g_after_size; ++i) line[n++] = g_after[i];
  line[n++] = '\n';
  const int saved = errno;  // a handler must not change errno for the code it interrupted
  while (::write(STDERR_FILENO, line, n) < 0 && errno == EINTR) {
  }
  errno = saved;
}

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
  if (g_announce) announce(sig);
}

}  // namespace

InterruptGuard::InterruptGuard(std::string_view announcement) {
  if (g_alive.exchange(true)) throw std::logic_error("InterruptGuard: another guard is alive");
  g_flag.store(false);
  g_signal = 0;
  g_announce = !announcement.empty();
  const std::size_t at = announcement.find("{signal}");
  g_announce_name = at != std::string_view::npos;
  g_before_size = copy_into(g_before, announcement.substr(0, at));
  g_after_size = at == std::string_view::npos ? 0 : copy_into(g_after, announcement.substr(at + 8));
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
  g_announce = false;
  g_alive.store(false);
}

const std::atomic<bool>& InterruptGuard::flag() const { return g_flag; }

int InterruptGuard::signal_number() const { return static_cast<int>(g_signal); }

const char* InterruptGuard::signal_name(int signal) {
  switch (signal) {
    case SIGINT: return "SIGINT";
    case SIGTERM: return "SIGTERM";
    case SIGHUP: return "SIGHUP";
    default: return "a signal";
  }
}

}  // namespace frictionlab::support
