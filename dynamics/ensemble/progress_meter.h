#pragma once
// Progress of an ensemble on stderr: runs done / total, runs per second over this session, and the
// time left at that rate. On a terminal one line is redrawn at most once a second; otherwise
// (a log file, a batch job) a line is written every `interval` seconds and at the end. Thread-safe.

#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

namespace frictionlab::dynamics::ensemble {

class ProgressMeter {
 public:
  /// `total` runs of which `done_before` were finished by an earlier session. `out` may be null
  /// (silent). `live`: redraw one line (a terminal).
  ProgressMeter(long total, long done_before, std::FILE* out, bool live, double interval = 30.0);

  /// One more run finished.
  void run_finished();
  /// The last line (and a line break after a live line).
  void finish();

  /// "1234/10240 runs (12.1 %), 3.52 runs/s, 42 min left" for `done` of this session after
  /// `elapsed` seconds (a pure function of its arguments, for tests).
  [[nodiscard]] static std::string line(long total, long done_before, long done_now, double elapsed);
  /// "45 s", "12 min", "3.2 h", "2.1 d".
  [[nodiscard]] static std::string duration(double seconds);

 private:
  void print(bool final_line);

  long total_;
  long done_before_;
  long done_now_ = 0;
  std::FILE* out_;
  bool live_;
  double interval_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_print_;
  std::mutex mutex_;
};

}  // namespace frictionlab::dynamics::ensemble
