#include "dynamics/ensemble/progress_meter.h"

#include <cmath>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics::ensemble {

ProgressMeter::ProgressMeter(long total, long done_before, std::FILE* out, bool live, double interval)
    : total_(total),
      done_before_(done_before),
      out_(out),
      live_(live),
      interval_(live ? 1.0 : interval),
      start_(std::chrono::steady_clock::now()),
      last_print_(start_) {}

std::string ProgressMeter::duration(double seconds) {
  if (!std::isfinite(seconds)) return "?";
  if (seconds < 99.5) return support::fixed(seconds, 0) + " s";
  if (seconds < 5940.0) return support::fixed(seconds / 60.0, 0) + " min";
  if (seconds < 172800.0) return support::significant(seconds / 3600.0, 2) + " h";
  return support::significant(seconds / 86400.0, 2) + " d";
}

std::string ProgressMeter::line(long total, long done_before, long done_now, double elapsed) {
  const long done = done_before + done_now;
  std::string s = std::to_string(done) + "/" + std::to_string(total) + " runs (" +
                  support::fixed(total > 0 ? 100.0 * static_cast<double>(done) / static_cast<double>(total) : 100.0, 1) +
                  " %)";
  if (done_now > 0 && elapsed > 0.0) {
    const double rate = static_cast<double>(done_now) / elapsed;
    s += ", " + support::significant(rate, 3) + " runs/s";
    if (done < total) s += ", " + duration(static_cast<double>(total - done) / rate) + " left";
  }
  return s;
}

void ProgressMeter::print(bool final_line) {
  if (!out_) return;
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::string text = "ensemble: " + line(total_, done_before_, done_now_, elapsed);
  if (live_) {
    std::fprintf(out_, "\r%s\033[K%s", text.c_str(), final_line ? "\n" : "");
  } else {
    std::fprintf(out_, "%s\n", text.c_str());
  }
  std::fflush(out_);
}

void ProgressMeter::run_finished() {
  const std::lock_guard<std::mutex> lock(mutex_);
  ++done_now_;
  const auto now = std::chrono::steady_clock::now();
  if (std::chrono::duration<double>(now - last_print_).count() >= interval_) {
    last_print_ = now;
    print(false);
  }
}

void ProgressMeter::finish() {
  const std::lock_guard<std::mutex> lock(mutex_);
  print(true);
}

}  // namespace frictionlab::dynamics::ensemble
