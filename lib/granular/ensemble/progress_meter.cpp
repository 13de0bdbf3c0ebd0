#include "granular/ensemble/progress_meter.hpp"

#include <unistd.h>

#include <cstdio>

namespace granular {

ProgressMeter::ProgressMeter(std::size_t total, std::string label, int enabled)
    : total_(total), label_(std::move(label)), enabled_(enabled < 0 ? ::isatty(STDERR_FILENO) != 0 : enabled != 0),
      start_(std::chrono::steady_clock::now()), last_draw_(start_) {}

ProgressMeter::~ProgressMeter() { finish(); }

void ProgressMeter::advance(std::size_t count) {
  done_ += count;
  if (!enabled_) return;
  const auto now = std::chrono::steady_clock::now();
  std::unique_lock lock(mutex_, std::try_to_lock);
  if (!lock.owns_lock() || now - last_draw_ < std::chrono::milliseconds(500)) return;
  last_draw_ = now;
  draw(false);
}

void ProgressMeter::finish() {
  std::lock_guard lock(mutex_);
  if (finished_) return;
  finished_ = true;
  if (enabled_) draw(true);
}

void ProgressMeter::draw(bool final) {
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const std::size_t done = done_.load();
  const double rate = elapsed > 0 ? static_cast<double>(done) / elapsed : 0;
  const double eta = rate > 0 ? static_cast<double>(total_ - std::min(done, total_)) / rate : 0;
  std::fprintf(stderr, "\r%s: %zu/%zu (%.1f%%)  %.1f/s  %s %.0f s   ", label_.c_str(), done, total_,
               total_ ? 100.0 * static_cast<double>(done) / static_cast<double>(total_) : 100.0, rate,
               final ? "took" : "ETA", final ? elapsed : eta);
  if (final) std::fputc('\n', stderr);
  std::fflush(stderr);
}

}  // namespace granular
