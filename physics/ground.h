#pragma once
// The ground of the DEM world: the height field under the grains (the
// floor, raised to the top of the fixed layer in three and of the static
// layer in bcre), in tiles of kTilePx pixels. Bullet pairs a grain with a
// height field whenever their bounds overlap and then scans the triangles
// under it; one window-wide field with bounds up to the lid was scanned by
// every moving grain on every step (7% of the run's time at 22,000 grains).
// A tile's bounds end just above its highest vertex, so grains on the pile,
// a static band above the fixed layer, never touch it.
#include <functional>
#include <memory>
#include <vector>

#include "src/grains.h"

class btCollisionObject;
class btCollisionShape;
class btHeightfieldTerrainShape;

namespace sandpic {

constexpr int kGroundPerPx = 4;  // vertices per pixel: a small grain (0.56 px) spans at least two
constexpr int kTilePx = 16;

class Ground {
 public:
  // `add` puts a static collider into the world, `remove` takes it out.
  using Add = std::function<std::unique_ptr<btCollisionObject>(btCollisionShape*, Vec2 centre)>;
  using Remove = std::function<void(btCollisionObject*)>;
  Ground(int width, int height, Add add, Remove remove);
  ~Ground();

  // Raises the ground to the upper outline of a grain of radius r centred
  // at p; r = 0 raises the nearest vertex to p.y.
  void raise(Vec2 p, double r);

 private:
  struct Tile {
    std::vector<float> heights;  // 2 rows (z = ±0.5) of vertices
    float top = 0;               // the bounds' upper edge
    std::unique_ptr<btHeightfieldTerrainShape> shape;
    std::unique_ptr<btCollisionObject> object;
  };
  void rebuild(int t);
  int width_, height_;
  Add add_;
  Remove remove_;
  std::vector<Tile> tiles_;
};

}  // namespace sandpic
