#include "src/progress.h"

#include <unistd.h>

#include <cstdio>

#include "src/errors.h"

namespace sandpic {

bool Progress::stderr_is_terminal() { return isatty(STDERR_FILENO) == 1; }

void Progress::start(const std::string& label, int64_t total) {
  label_ = label;
  total_ = total;
  start_ = last_ = std::chrono::steady_clock::now();
}

void Progress::update(int64_t done) {
  if (cancel_ && cancel_->load(std::memory_order_relaxed)) throw Cancelled("cancelled");
  if (fraction_ && total_ > 0) fraction_->store(double(done) / double(total_), std::memory_order_relaxed);
  if (!enabled_) return;
  auto now = std::chrono::steady_clock::now();
  if (now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  draw(done);
}

void Progress::draw(int64_t done) {
  double frac = total_ > 0 ? double(done) / double(total_) : 1.0;
  double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  double eta = frac > 0 ? elapsed * (1 - frac) / frac : 0;
  constexpr int kWidth = 30;
  char bar[kWidth + 1];
  int filled = int(frac * kWidth);
  for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '=' : ' ';
  bar[kWidth] = 0;
  std::fprintf(stderr, "\r%s [%s] %3d%% %lld/%lld ETA %.0fs ", label_.c_str(), bar, int(frac * 100),
               (long long)done, (long long)total_, eta);
  std::fflush(stderr);
}

void Progress::finish() {
  if (fraction_) fraction_->store(1.0, std::memory_order_relaxed);
  if (!enabled_) return;
  draw(total_);
  std::fprintf(stderr, "\n");
}

}  // namespace sandpic
