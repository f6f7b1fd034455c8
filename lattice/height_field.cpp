#include "lattice/height_field.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>

#include <tbb/parallel_for.h>

#include "src/rng.h"

namespace sandpic {

HeightField::HeightField(int columns, double column_width_px, double ceiling_px, std::vector<SlopeRule> rules)
    : h_(size_t(columns + 2 * kPad), INFINITY),
      columns_(columns),
      stacks_(size_t(columns)),
      width_(column_width_px),
      ceiling_(ceiling_px) {
  std::fill(h_.begin() + kPad, h_.end() - kPad, 0.0);
  for (const SlopeRule& r : rules) {
    Slopes s{r, {}};
    s.rule.window = std::clamp(r.window, 1, kMaxWindow);
    for (auto& bits : s.steep) bits.assign(size_t(columns + 63) / 64, 0);  // a flat floor
    slopes_.push_back(std::move(s));
  }
}

double HeightField::max_height() const { return *std::max_element(h_.begin() + kPad, h_.end() - kPad); }

// Branch-free over the window (which k decides is unpredictable); the walls
// are padding of infinite height.
bool HeightField::too_steep(int c, int dir, double t, int window) const {
  const double* p = h_.data() + kPad + c;
  const double top = *p;
  bool any = false;
  for (int k = 1; k <= window; ++k) any |= top - p[dir * k] > k * t;
  return any;
}

bool HeightField::unstable(int c, int dir, const SlopeRule& rule) const {
  return too_steep(c, dir, rule.drop_per_column, rule.window);
}

// The slide from c toward dir: to the next column a grain may rest on, unless
// it is caught on the way (a chance per column passed) where the flank is no
// steeper than the trap slope. Only called with a trap rate (settle's fast
// path goes to next_resting without one).
int HeightField::slide(const Slopes& s, int c, int dir, uint64_t seed, uint64_t id, int& draws, bool& caught) const {
  const int stop = next_resting(s, c, dir);
  const double q = s.rule.trap_rate;
  if (stop == c) return stop;
  const double log_miss = std::log1p(-std::min(q, 0.999999));
  for (int at = c;;) {
    const double u = uniform(seed, Stream::LatticeTrap, id, uint64_t(draws++));
    const double n = 1 + std::floor(std::log1p(-u) / log_miss);
    if (n >= std::abs(stop - at)) return stop;
    at += dir * int(n);
    if (!too_steep(at, dir, s.rule.trap_drop_per_column, s.rule.window) &&
        !too_steep(at, -dir, s.rule.trap_drop_per_column, s.rule.window)) {
      caught = true;
      return at;
    }
  }
}

// How much the steepest look-ahead slope exceeds the rule's, per column.
double HeightField::excess(int c, int dir, const SlopeRule& rule) const {
  double worst = -INFINITY;
  for (int k = 1; k <= rule.window; ++k) worst = std::max(worst, (height(c) - height(c + dir * k)) / k);
  return worst - rule.drop_per_column;
}

bool HeightField::steep(const Slopes& s, int c, int dir) const {
  if (c < 0 || c >= columns_) return false;
  return (s.steep[dir > 0 ? 0 : 1][size_t(c) >> 6] >> (c & 63)) & 1;
}

// The first column from c on, going dir, that is not steep toward dir.
int HeightField::next_resting(const Slopes& s, int c, int dir) const {
  const std::vector<uint64_t>& bits = s.steep[dir > 0 ? 0 : 1];
  size_t w = size_t(c) >> 6;
  if (dir > 0) {
    uint64_t free = ~bits[w] & (~0ull << (c & 63));
    while (free == 0) free = ~bits[++w];  // the last column is never steep toward its wall
    return int(w * 64 + size_t(std::countr_zero(free)));
  }
  uint64_t free = ~bits[w] & (~0ull >> (63 - (c & 63)));
  while (free == 0) free = ~bits[--w];
  return int(w * 64 + 63 - size_t(std::countl_zero(free)));
}

int HeightField::settle(int c, int r, uint64_t seed, uint64_t id) const {
  const Slopes& s = slopes_[size_t(r)];
  bool right = steep(s, c, +1), left = steep(s, c, -1);
  if (!right && !left) return c;
  int dir = right && !left ? 1 : left && !right ? -1 : 0;
  if (dir == 0) {  // on a peak: the steeper side, a coin if equal
    double er = excess(c, +1, s.rule), el = excess(c, -1, s.rule);
    dir = er > el ? 1 : el > er ? -1 : (uniform(seed, Stream::LatticeSlide, id) < 0.5 ? -1 : 1);
  }
  // A grain slides on in its direction while that side is too steep, then
  // keeps going downhill for its run-out; in a pit it may turn.
  int draws = 0;
  for (int turns = 0;;) {
    if (s.rule.trap_rate > 0) {
      bool caught = false;
      c = slide(s, c, dir, seed, id, draws, caught);
      if (caught) return c;  // caught on the flank: no run-out
    } else {
      c = next_resting(s, c, dir);
    }
    for (int coast = s.rule.runout; coast > 0 && height(c + dir) < height(c) && !steep(s, c, -dir); --coast)
      c += dir;
    if (steep(s, c, dir)) continue;
    if (turns++ < 2 && steep(s, c, -dir)) {
      dir = -dir;
      continue;
    }
    return c;
  }
}

int HeightField::room_near(int c, double rise) const {
  for (int d = 0; d < columns(); ++d)
    for (int j : {c - d, c + d})
      if (j >= 0 && j < columns() && height(j) + rise <= ceiling_) return j;
  return -1;
}

namespace {

// Two doubles at once (GCC/Clang vector extensions: SSE2, NEON or plain code).
using Pair = double __attribute__((vector_size(16)));
using PairMask = long long __attribute__((vector_size(16)));
Pair pair_at(const double* p) {
  Pair v;
  std::memcpy(&v, p, sizeof v);
  return v;
}

// The steep bits toward `dir` of 2·P columns from p[0] on, as a bit mask:
// two columns at a time, branch-free over the window (P known to the
// compiler, so the pairs stay in registers).
template <int P>
uint32_t steep_mask(const double* p, int dir, int window, double t) {
  Pair tops[P];
  PairMask any[P];
  for (int m = 0; m < P; ++m) {
    tops[m] = pair_at(p + 2 * m);
    any[m] = PairMask{0, 0};
  }
  for (int k = 1; k <= window; ++k) {
    const double reach = k * t;  // as unstable(): the same rounding
    const Pair r = {reach, reach};
    for (int m = 0; m < P; ++m) any[m] |= tops[m] - pair_at(p + 2 * m + dir * k) > r;
  }
  uint32_t steep = 0;
  for (int m = 0; m < P; ++m) steep |= uint32_t(any[m][0] & 1) << (2 * m) | uint32_t(any[m][1] & 1) << (2 * m + 1);
  return steep;
}

}  // namespace

// The steep bits toward side's direction of columns first..first+count-1
// (count <= kShortWindow + 1), from the heights. Columns outside the window
// (the padding) are computed and not kept.
void HeightField::recompute(Slopes& s, int side, int first, int count) {
  const int dir = side == 0 ? 1 : -1, window = s.rule.window;
  const double t = s.rule.drop_per_column, *p = h_.data() + kPad + first;
  static_assert(kShortWindow + 1 <= 10 && kPad >= 2 * kShortWindow + 2);
  uint32_t steep = 0;
  switch ((count + 1) / 2) {
    case 1: steep = steep_mask<1>(p, dir, window, t); break;
    case 2: steep = steep_mask<2>(p, dir, window, t); break;
    case 3: steep = steep_mask<3>(p, dir, window, t); break;
    case 4: steep = steep_mask<4>(p, dir, window, t); break;
    default: steep = steep_mask<5>(p, dir, window, t); break;
  }
  const int lo = std::max(first, 0), hi = std::min(first + count - 1, columns_ - 1);
  if (lo > hi) return;
  const int n = hi - lo + 1, at = lo & 63;
  const uint64_t field = (1ull << n) - 1, value = (uint64_t(steep) >> (lo - first)) & field;
  std::vector<uint64_t>& bits = s.steep[side];
  uint64_t& word = bits[size_t(lo) >> 6];
  word = (word & ~(field << at)) | (value << at);
  if (at + n > 64) {  // into the next word (at > 0 here: n < 64)
    uint64_t& next = bits[size_t(lo >> 6) + 1];
    next = (next & ~(field >> (64 - at))) | (value >> (64 - at));
  }
}

// Column c rose. It may have become steep on either side; the columns within
// the window that look at it can only have become less steep. A short window
// recomputes them all at once (c-k..c toward +x, c..c+k toward -x); a long
// one looks again only at those marked steep, found by scanning the bit words.
void HeightField::refresh(Slopes& s, int c) {
  const int k = s.rule.window;
  if (k <= kShortWindow) {
    recompute(s, 0, c - k, k + 1);
    recompute(s, 1, c, k + 1);
    return;
  }
  for (int side = 0; side < 2; ++side) {
    const int dir = side == 0 ? 1 : -1;
    std::vector<uint64_t>& bits = s.steep[side];
    auto set = [&](int j, bool steep) {
      uint64_t bit = 1ull << (j & 63);
      uint64_t& word = bits[size_t(j) >> 6];
      word = steep ? word | bit : word & ~bit;
    };
    set(c, unstable(c, dir, s.rule));
    // The neighbours that look at c: c-k..c-1 toward +x, c+1..c+k toward -x.
    const int lo = std::max(0, side == 0 ? c - k : c + 1), hi = std::min(columns_ - 1, side == 0 ? c - 1 : c + k);
    for (int w = lo >> 6; w <= (hi >> 6) && lo <= hi; ++w) {
      uint64_t word = bits[size_t(w)];
      if (w == lo >> 6) word &= ~0ull << (lo & 63);
      if (w == hi >> 6) word &= ~0ull >> (63 - (hi & 63));
      for (; word; word &= word - 1) {
        const int j = w * 64 + std::countr_zero(word);
        // A steep neighbour usually stays steep by its next column alone.
        if (j + dir != c && height(j) - height(j + dir) > s.rule.drop_per_column) continue;
        set(j, unstable(j, dir, s.rule));
      }
    }
  }
}

double HeightField::deposit(int c, uint8_t cls, double area_px) {
  double base = height(c), rise = area_px / width_;
  h_[size_t(c + kPad)] = base + rise;
  stacks_[size_t(c)].push_back(Deposit{float(base + rise), cls});
  for (Slopes& s : slopes_) refresh(s, c);
  return base + rise / 2;
}

cv::Mat HeightField::class_map(int width, int height, uint8_t empty, double surface_px,
                               const std::vector<double>& share) const {
  cv::Mat map(height, width, CV_8U, cv::Scalar(empty));
  const double columns_per_px = 1.0 / width_;
  // With shares, a mixed column's deposit tops are redrawn in proportion to
  // rise · share, its top kept; without, they are the stack's own.
  std::vector<std::vector<double>> redrawn(share.empty() ? 0 : static_cast<size_t>(columns_));
  tbb::parallel_for(0, int(redrawn.size()), [&](int c) {
    const std::vector<Deposit>& stack = stacks_[size_t(c)];
    auto weight = [&](size_t k) { return stack[k].cls < share.size() ? share[stack[k].cls] : 1.0; };
    bool mixed = false;
    for (size_t k = 1; k < stack.size() && !mixed; ++k) mixed = weight(k) != weight(0);
    if (!mixed) return;
    std::vector<double>& t = redrawn[size_t(c)];
    t.resize(stack.size());
    double below = 0, sum = 0;
    for (size_t k = 0; k < stack.size(); ++k) {
      sum += (double(stack[k].top) - below) * weight(k);
      below = stack[k].top;
      t[k] = sum;
    }
    for (size_t k = 0; k + 1 < stack.size(); ++k) t[k] *= below / sum;
    t.back() = below;
  });
  tbb::parallel_for(0, width, [&](int x) {
    int c = std::min(columns() - 1, int((x + 0.5) * columns_per_px));
    const std::vector<Deposit>& stack = stacks_[size_t(c)];
    const std::vector<double>* t = redrawn.empty() || redrawn[size_t(c)].empty() ? nullptr : &redrawn[size_t(c)];
    // The loose layer: tops above `from` drawn `stretch` times as far above it.
    const double top = this->height(c), loose = std::min(top, kLooseLayerPx);
    const double from = top - loose, stretch = loose > 0 ? (loose + surface_px) / loose : 1;
    auto drawn_top = [&](size_t k) {
      const double v = t ? (*t)[k] : double(stack[k].top);
      return v <= from ? v : from + (v - from) * stretch;
    };
    size_t k = 0;
    for (int i = 0; i < height; ++i) {  // pixel rows from the floor up
      double centre = i + 0.5;
      while (k < stack.size() && drawn_top(k) <= centre) ++k;
      if (k == stack.size()) break;
      map.at<uint8_t>(height - 1 - i, x) = stack[k].cls;
    }
  });
  return map;
}

}  // namespace sandpic
