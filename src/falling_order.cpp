#include "src/falling_order.h"

#include <algorithm>

#include <tbb/parallel_for.h>

#include "src/rng.h"

namespace sandpic {

FallingOrder falling_order(const Segmentation& seg, const GrainSet& g, uint64_t layout_seed) {
  const size_t units = seg.units.size();
  FallingOrder order;
  // Counting sort of grains by unit; each unit then sorts its own grains.
  order.unit_begin.assign(units + 1, 0);
  for (int32_t u : seg.unit_of) ++order.unit_begin[size_t(u) + 1];
  for (size_t u = 0; u < units; ++u) order.unit_begin[u + 1] += order.unit_begin[u];
  order.grain.resize(seg.unit_of.size());
  std::vector<int64_t> at(order.unit_begin.begin(), order.unit_begin.end() - 1);
  for (size_t id = 0; id < seg.unit_of.size(); ++id) order.grain[at[seg.unit_of[id]]++] = int32_t(id);

  tbb::parallel_for(size_t(0), units, [&](size_t u) {
    const Vec2 outlet = seg.units[u].outlet();
    struct Key {
      double d2;
      uint64_t tie;
      int32_t id;
    };
    std::vector<Key> keys;
    keys.reserve(size_t(order.unit_begin[u + 1] - order.unit_begin[u]));
    for (int64_t i = order.unit_begin[u]; i < order.unit_begin[u + 1]; ++i) {
      int32_t id = order.grain[i];
      keys.push_back({(g.position(id) - outlet).squaredNorm(), key(layout_seed, Stream::GrainTies, uint64_t(id)), id});
    }
    std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
      return a.d2 != b.d2 ? a.d2 < b.d2 : (a.tie != b.tie ? a.tie < b.tie : a.id < b.id);
    });
    for (size_t i = 0; i < keys.size(); ++i) order.grain[order.unit_begin[u] + int64_t(i)] = keys[i].id;
  });
  return order;
}

}  // namespace sandpic
