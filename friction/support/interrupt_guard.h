#pragma once
// Stopping a long job cleanly: while an InterruptGuard lives, SIGINT (Ctrl-C), SIGTERM (kill) and
// SIGHUP (the terminal went away) only raise a flag, which the job polls between steps to stop
// and still write what it has. A second signal while the flag is up ends the process the usual
// way (the impatient user's Ctrl-C Ctrl-C). The guard restores the previous handlers when it dies.
//
// A job that may be killed soon after the signal can say at once why it stops: given an
// announcement, the guard writes it to stderr from the handler on the first signal. mpirun, sent
// SIGTERM (or SIGINT), forwards it to every rank and sends SIGKILL one second later (Open MPI's
// odls_base_sigkill_timeout): too soon for a job to finish its step and print its usual last line.
//
// The flag is process-wide (signals are): at most one guard may live at a time.

#include <atomic>
#include <string_view>

namespace frictionlab::support {

class InterruptGuard {
 public:
  /// Installs the handlers and lowers the flag. Throws std::logic_error if another guard lives,
  /// std::system_error if a handler cannot be installed. A non-empty `announcement` is written to
  /// stderr (one write(2), a newline added) when the first signal arrives, "{signal}" in it
  /// replaced by the signal's name; it is cut to 480 bytes.
  explicit InterruptGuard(std::string_view announcement = {});
  /// Restores the handlers that were installed before.
  ~InterruptGuard();
  InterruptGuard(const InterruptGuard&) = delete;
  InterruptGuard& operator=(const InterruptGuard&) = delete;

  /// Raised by the first SIGINT, SIGTERM or SIGHUP (to pass to a job as its cancel flag).
  [[nodiscard]] const std::atomic<bool>& flag() const;
  [[nodiscard]] bool interrupted() const { return flag().load(); }
  /// The signal that raised the flag (0 if none).
  [[nodiscard]] int signal_number() const;

  /// "SIGINT", "SIGTERM", "SIGHUP" (or "a signal") for one of the signals the guard handles.
  [[nodiscard]] static const char* signal_name(int signal);
};

}  // namespace frictionlab::support
