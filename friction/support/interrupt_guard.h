#pragma once
// Stopping a long job cleanly: while an InterruptGuard lives, SIGINT (Ctrl-C), SIGTERM (kill) and
// SIGHUP (the terminal went away) only raise a flag, which the job polls between steps to stop
// and still write what it has. A second signal while the flag is up ends the process the usual
// way (the impatient user's Ctrl-C Ctrl-C). The guard restores the previous handlers when it dies.
//
// The flag is process-wide (signals are): at most one guard may live at a time.

#include <atomic>

namespace frictionlab::support {

class InterruptGuard {
 public:
  /// Installs the handlers and lowers the flag. Throws std::logic_error if another guard lives,
  /// std::system_error if a handler cannot be installed.
  InterruptGuard();
  /// Restores the handlers that were installed before.
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Raised by the first SIGINT, SIGTERM or SIGHUP (to pass to a job as its cancel flag).
  [[nodiscard]] const std::atomic<bool>& flag() const;
  [[nodiscard]] bool interrupted() const { return flag().load(); }
  /// The signal that raised the flag (0 if none).
  [[nodiscard]] int signal_number() const;
};

}  // namespace frictionlab::support
