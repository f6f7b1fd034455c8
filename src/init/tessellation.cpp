// paper §4.3: tessellation of the region into rectangular cells: uniform
// (Fig. 4), rows growing downward with random widths (Fig. 5), or full-width
// strips for regular patterns (§9, Fig. 18).
#include <algorithm>
#include <cmath>

#include "src/init/init.h"
#include "src/rng.h"

namespace sandpic {
namespace {

// Splits [0, total) into pieces drawn by `next`; a remainder smaller than
// `smallest` joins the last piece, so no sliver cell is made.
template <class Next>
std::vector<int> split(int total, double smallest, Next next) {
  std::vector<int> cuts{0};
  for (int at = 0; at < total;) {
    int size = std::max(1, int(std::lround(next(double(at)))));
    if (total - (at + size) < smallest) size = total - at;
    at = std::min(total, at + size);
    cuts.push_back(at);
  }
  return cuts;
}

std::vector<int> even(int total, double size) {
  std::vector<int> cuts;
  for (double at = 0; at < total; at += size) cuts.push_back(int(std::lround(at)));
  cuts.push_back(total);
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
  return cuts;
}

void add_row(Tessellation& t, int y0, int y1, const std::vector<int>& xs) {
  for (size_t i = 0; i + 1 < xs.size(); ++i) t.cells.push_back(Cell{xs[i], y0, xs[i + 1], y1});
}

}  // namespace

Tessellation tessellate(const Scene& s) {
  const auto& in = s.init;
  const int W = s.window.width, H = s.region.height;
  Tessellation t;
  if (in.tessellation == TessellationKind::Uniform) {
    std::vector<int> xs = even(W, in.cell_width), ys = even(H, in.cell_height);
    for (size_t r = 0; r + 1 < ys.size(); ++r) add_row(t, ys[r], ys[r + 1], xs);
    return t;
  }
  std::vector<int> ys;
  if (in.tessellation == TessellationKind::Varying) {
    // Fig. 5: distant (upper) rows are lower than near ones.
    ys = split(H, in.row_height_min, [&](double y) {
      return in.row_height_min + (in.row_height_max - in.row_height_min) * (y / H);
    });
  } else {
    KeyedRng rng(s.layout(), Stream::Tessellation, ~0ull);
    ys = split(H, in.row_height_min, [&](double) { return rng.real(in.row_height_min, in.row_height_max); });
  }
  for (size_t r = 0; r + 1 < ys.size(); ++r) {
    if (in.tessellation == TessellationKind::Strips) {
      add_row(t, ys[r], ys[r + 1], {0, W});
      continue;
    }
    KeyedRng rng(s.layout(), Stream::Tessellation, r);
    add_row(t, ys[r], ys[r + 1],
            split(W, in.cell_width_min, [&](double) { return rng.real(in.cell_width_min, in.cell_width_max); }));
  }
  return t;
}

}  // namespace sandpic
