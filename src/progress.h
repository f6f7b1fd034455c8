#pragma once
// A progress bar for long work, on stderr when it is a terminal only.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>

namespace sandpic {

class Progress {
 public:
  // `fraction`, when given, is kept at done / total for another thread to
  // read (the studio's render status), whether or not a bar is drawn. When
  // another thread sets `cancel`, the next update throws Cancelled: the
  // backends call update from their serial loop, between steps, so the run
  // unwinds with nothing half-done and nothing written.
  explicit Progress(bool enabled, std::atomic<double>* fraction = nullptr,
                    const std::atomic<bool>* cancel = nullptr)
      : enabled_(enabled), fraction_(fraction), cancel_(cancel) {}
  static bool stderr_is_terminal();

  void start(const std::string& label, int64_t total);
  void update(int64_t done);  // cheap: redraws at most ten times a second; may throw Cancelled
  void finish();

 private:
  void draw(int64_t done);
  bool enabled_;
  std::atomic<double>* fraction_;
  const std::atomic<bool>* cancel_;
  std::string label_;
  int64_t total_ = 0;
  std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace sandpic
