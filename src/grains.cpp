#include "src/grains.h"

namespace sandpic {

std::array<int64_t, kClasses> GrainSet::per_class() const {
  std::array<int64_t, kClasses> n{};
  for (uint8_t c : cls) ++n[c];
  return n;
}

GrainSet empty_region(const Scene& s) {
  GrainSet g;
  g.width = s.window.width;
  g.height = s.region.height;
  g.cls.assign(size_t(g.size()), 0);
  return g;
}

}  // namespace sandpic
