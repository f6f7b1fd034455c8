// paper §4.4, Algorithm 1: fill each cell with one dominant and one
// non-dominant class. With dominant share 0.8 and proportions 3/8, 3/8, 1/8,
// 1/8 the expected overall shares are 0.342, 0.342, 0.158, 0.158.
#include <array>

#include <tbb/parallel_for.h>

#include "src/errors.h"
#include "src/init/init.h"
#include "src/rng.h"

namespace sandpic {
namespace {

void draw_classes(const Scene& s, size_t id, Cell& c) {
  KeyedRng rng(s.layout(), Stream::CellFill, id);
  c.dominant = rng.pick(s.grains.proportions);  // line 2
  // Line 4: the non-dominant class uniformly among the other three.
  std::array<double, kClasses> others{1, 1, 1, 1};
  others[c.dominant] = 0;
  c.secondary = rng.pick(others);
}

}  // namespace

void fill_cells(const Scene& s, Tessellation& t, GrainSet& g) {
  for (size_t i = 0; i < t.cells.size(); ++i) draw_classes(s, i, t.cells[i]);
  for (const CellOverride& o : s.init.cell_overrides) {
    if (o.cell >= int(t.cells.size()))
      throw key_error("init.cell_overrides", "cell " + std::to_string(o.cell) + " does not exist (the tessellation has " +
                                                 std::to_string(t.cells.size()) + " cells)");
    t.cells[o.cell].dominant = o.dominant;
    t.cells[o.cell].secondary = o.secondary;
  }
  // Each grain's draw is keyed by its id, so cells fill in any order.
  const double share = s.init.dominant_share;
  const uint64_t seed = s.layout();
  tbb::parallel_for(size_t(0), t.cells.size(), [&](size_t i) {
    const Cell& c = t.cells[i];
    for (int y = c.y0; y < c.y1; ++y)
      for (int x = c.x0; x < c.x1; ++x) {
        int64_t id = int64_t(y) * g.width + x;
        g.cls[id] = uint8_t(uniform(seed, Stream::GrainFill, id) < share ? c.dominant : c.secondary);  // lines 7-11
      }
  });
}

}  // namespace sandpic
