#pragma once
// Randomness keyed by (seed, stream, id), never by thread or call order, so a
// TBB schedule cannot change a picture (STYLE.md, pbrt-v4).
#include <cstdint>

namespace sandpic {

// What a random number is for; each stream is independent of the others.
enum class Stream : uint64_t {
  Tessellation = 1,  // cell sizes
  CellFill,          // paper §4.4, Algorithm 1 lines 2-5: classes per cell
  GrainFill,         // Algorithm 1 line 7: dominant or not, per grain
  Ellipses,          // automatic segmentation
  UnitOrder,         // paper §6: random order within a row of units
  GrainTies,         // paper §6: equal distances to the outlet
  OutletJitter,      // release point across the outlet (physics seed)
  LatticeSlide,      // lattice: left/right ties (physics seed)
  Sketch,            // paper §5.2: eccentricities and narrow-ellipse angles per crossing
  Figure,            // paper §10: C1 or C2 for sand on a figure, per pixel
  Pattern,           // paper §10, Fig. 18: a row's unit of two ellipses
  Area,              // paper §10, Fig. 17: an area's own layout seed
  LatticeTrap,       // lattice: where a sliding grain is caught on a flank (physics seed)
};

inline uint64_t mix64(uint64_t z) {  // splitmix64 finaliser
  z += 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

inline uint64_t key(uint64_t seed, Stream s, uint64_t id, uint64_t k = 0) {
  return mix64(mix64(mix64(seed) ^ (static_cast<uint64_t>(s) * 0x632be59bd9b4e019ull)) ^
               (mix64(id) + k * 0xd6e8feb86659fd93ull));
}

// Uniform in [0, 1) with 53 random bits.
inline double unit_real(uint64_t h) { return static_cast<double>(h >> 11) * 0x1.0p-53; }

inline double uniform(uint64_t seed, Stream s, uint64_t id, uint64_t k = 0) {
  return unit_real(key(seed, s, id, k));
}

// A short sequential stream for one (seed, stream, id): draw i is key(..., i).
class KeyedRng {
 public:
  KeyedRng(uint64_t seed, Stream s, uint64_t id) : seed_(seed), stream_(s), id_(id) {}
  double real() { return uniform(seed_, stream_, id_, next_++); }
  double real(double lo, double hi) { return lo + (hi - lo) * real(); }
  // Index drawn with the given (unnormalised, non-negative) weights.
  template <class W>
  int pick(const W& weights) {
    double total = 0;
    for (double w : weights) total += w;
    double r = real() * total;
    int i = 0;
    for (double w : weights) {
      if (r < w) return i;
      r -= w;
      ++i;
    }
    return i - 1;
  }

 private:
  uint64_t seed_;
  Stream stream_;
  uint64_t id_;
  uint64_t next_ = 0;
};

}  // namespace sandpic
