#pragma once
// A one-line progress report (done/total, rate, ETA) on stderr, redrawn at most twice a
// second. Silent unless enabled, and by default enabled only when stderr is a terminal, so
// logs and pipes stay clean. Thread-safe: any worker may call advance().
#include <atomic>
#include <chrono>
#include <cstddef>
#include <mutex>
#include <string>

namespace granular {

class ProgressMeter {
 public:
  /// `enabled`: -1 = when stderr is a terminal, 0 = never, 1 = always.
  ProgressMeter(std::size_t total, std::string label, int enabled = -1);
  ~ProgressMeter();
  void advance(std::size_t count = 1);
  /// Prints the final line (if enabled) once.
  void finish();
  std::size_t done() const { return done_.load(); }

 private:
  void draw(bool final);
  std::size_t total_;
  std::string label_;
  bool enabled_;
  bool finished_ = false;
  std::atomic<std::size_t> done_{0};
  std::chrono::steady_clock::time_point start_, last_draw_;
  std::mutex mutex_;
};

}  // namespace granular
