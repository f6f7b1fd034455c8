#include "validate/bench/falling_sand.h"

#include <algorithm>
#include <cmath>

#include "src/release.h"
#include "src/rng.h"

namespace sandpic {

FallingSand falling_sand(int width, int height, std::span<const int32_t> columns, int per_tick, uint64_t seed) {
  enum : uint8_t { kEmpty = 0, kMoving = 1, kResting = 2 };
  FallingSand out;
  cv::Mat grid = cv::Mat::zeros(height, width, CV_8U);
  uint8_t* cell = grid.ptr<uint8_t>();
  const int64_t n = int64_t(columns.size());
  // The moving grains as cell indices, in the order they entered: the lower
  // ones (older) move first, as a bottom-up sweep of the grid would.
  std::vector<int32_t> moving, still_moving;
  uint64_t coin = seed;
  int64_t next = 0;
  // A cell below a grain that counts as ground: the floor, a wall, a resting grain.
  auto ground = [&](int x, int y) { return y >= height || x < 0 || x >= width || cell[y * width + x] == kResting; };
  while (next < n || !moving.empty()) {
    ++out.ticks;
    bool progress = false;
    for (int r = 0; r < per_tick && next < n; ++r) {
      const int32_t at = std::clamp(columns[size_t(next)], 0, width - 1);
      if (cell[at] != kEmpty) break;  // the entry cell is taken: this grain waits a tick
      cell[at] = kMoving;
      moving.push_back(at);
      ++next;
      progress = true;
    }
    still_moving.clear();
    for (int32_t at : moving) {
      const int x = at % width, y = at / width;
      int32_t to = -1;
      if (y + 1 < height) {
        if (cell[at + width] == kEmpty) {
          to = at + width;
        } else {
          coin = mix64(coin);
          const int first = coin & 1 ? 1 : -1;
          for (int side : {first, -first})
            if (x + side >= 0 && x + side < width && cell[at + width + side] == kEmpty) {
              to = at + width + side;
              break;
            }
        }
      }
      if (to >= 0) {
        cell[at] = kEmpty;
        cell[to] = kMoving;
        still_moving.push_back(to);
        ++out.moves;
        progress = true;
      } else if (ground(x, y + 1) && ground(x - 1, y + 1) && ground(x + 1, y + 1)) {
        cell[at] = kResting;  // for good: resting cells never empty
        ++out.settled;
        progress = true;
      } else {
        still_moving.push_back(at);  // held up by a moving grain: tries again next tick
      }
    }
    std::swap(moving, still_moving);
    if (!progress) {  // the top row is full where the rest would enter
      out.lost = n - next;
      break;
    }
  }
  out.grid = grid == kResting;
  out.grid /= 255;
  return out;
}

std::vector<int32_t> entry_columns(const Scene& s, const Prepared& p) {
  const ReleaseModel model = release_model(s);
  std::vector<int32_t> columns(p.order.grain.size());
  for (size_t u = 0; u < p.seg.units.size(); ++u) {
    const Outlet o = outlet(model, p.seg.units[u]);
    for (int64_t i = p.order.unit_begin[u]; i < p.order.unit_begin[u + 1]; ++i)
      columns[size_t(i)] = int32_t(std::floor(exit_x(model, o, p.order.grain[size_t(i)])));
  }
  return columns;
}

}  // namespace sandpic
