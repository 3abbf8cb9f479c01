#pragma once
// Progress of a batch of runs on stderr: one line when a run starts and one when it ends (its
// termination reason and wall time), and, when stderr is a terminal, a compact live status line
// (runs done, and the simulated time of each run in flight) redrawn a few times a second.
// Thread-safe: workers call started()/finished() and publish their simulated time through
// slot_time(); lines never interleave.

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace frictionlab::dynamics::paper {

class RunProgress {
 public:
  /// `total` runs on `slots` workers, written to `out` (stderr). `live`: draw the status line.
  RunProgress(int total, int slots, std::FILE* out, bool live);
  ~RunProgress();
  RunProgress(const RunProgress&) = delete;
  RunProgress& operator=(const RunProgress&) = delete;

  /// Worker `slot` begins run `name` that ends at simulated time `t_end` (s).
  void started(int slot, const std::string& name, double t_end);
  /// Worker `slot` is done; `line` says how (no newline).
  void finished(int slot, const std::string& line);
  /// A line that is neither a start nor an end (why a run is redone); no newline.
  void note(const std::string& line);
  /// Where worker `slot` publishes its simulated time (s).
  [[nodiscard]] std::atomic<double>* slot_time(int slot) { return &slots_[static_cast<std::size_t>(slot)].t; }
  /// Stops the status line (also done by the destructor).
  void stop();

 private:
  struct Slot {
    std::atomic<double> t{0.0};
    std::string name;  // guarded by mutex_
    double t_end = 0.0;
    bool busy = false;
  };
  [[nodiscard]] std::string counter() const;  // "[3/30 done] "; mutex_ held
  void print_line(const std::string& line);  // mutex_ held
  void draw_status();                         // mutex_ held
  void clear_status();                        // mutex_ held
  void monitor();

  int total_;
  int done_ = 0;
  std::FILE* out_;
  bool live_;
  std::vector<Slot> slots_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool status_drawn_ = false;
  std::chrono::steady_clock::time_point start_;
  std::thread monitor_;
};

}  // namespace frictionlab::dynamics::paper
