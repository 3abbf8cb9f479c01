#include "dynamics/paper/run_progress.h"

#include <cmath>

#include "friction/support/number_format.h"

namespace frictionlab::dynamics::paper {
namespace {

constexpr auto kStatusRefresh = std::chrono::milliseconds(250);
constexpr std::size_t kStatusWidth = 160;  // characters; longer status lines are cut

}  // namespace

RunProgress::RunProgress(int total, int slots, std::FILE* out, bool live)
    : total_(total), out_(out), live_(live), slots_(static_cast<std::size_t>(slots)),
      start_(std::chrono::steady_clock::now()) {
  if (live_) monitor_ = std::thread([this] { monitor(); });
}

RunProgress::~RunProgress() { stop(); }

void RunProgress::stop() {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
    clear_status();
  }
  wake_.notify_all();
  if (monitor_.joinable()) monitor_.join();
}

void RunProgress::started(int slot, const std::string& name, double t_end) {
  std::lock_guard lock(mutex_);
  Slot& s = slots_[static_cast<std::size_t>(slot)];
  s.t.store(0.0, std::memory_order_relaxed);
  s.name = name;
  s.t_end = t_end;
  s.busy = true;
  print_line(counter() + "start " + name);
}

void RunProgress::finished(int slot, const std::string& line) {
  std::lock_guard lock(mutex_);
  slots_[static_cast<std::size_t>(slot)].busy = false;
  ++done_;
  print_line(counter() + line);
}

void RunProgress::note(const std::string& line) {
  std::lock_guard lock(mutex_);
  print_line(counter() + line);
}

std::string RunProgress::counter() const {
  return "[" + std::to_string(done_) + "/" + std::to_string(total_) + " done] ";
}

void RunProgress::print_line(const std::string& line) {
  clear_status();
  std::fprintf(out_, "%s\n", line.c_str());
  if (live_ && !stopping_) draw_status();
  std::fflush(out_);
}

void RunProgress::clear_status() {
  if (status_drawn_) std::fputs("\r\033[K", out_);
  status_drawn_ = false;
}

void RunProgress::draw_status() {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string line = std::to_string(done_) + "/" + std::to_string(total_) + " done, " + support::fixed(elapsed, 0) + " s |";
  for (const Slot& s : slots_) {
    if (!s.busy) continue;
    line += " " + s.name + " t=" + support::significant(s.t.load(std::memory_order_relaxed), 4) + "/" +
            support::significant(s.t_end, 4) + " s |";
  }
  if (line.size() > kStatusWidth) line.resize(kStatusWidth);
  std::fprintf(out_, "\r\033[K%s", line.c_str());
  std::fflush(out_);
  status_drawn_ = true;
}

void RunProgress::monitor() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    draw_status();
    wake_.wait_for(lock, kStatusRefresh, [this] { return stopping_; });
  }
}

}  // namespace frictionlab::dynamics::paper
