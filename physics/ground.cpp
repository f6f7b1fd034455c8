#include "physics/ground.h"

#include <algorithm>
#include <cmath>

#include <btBulletCollisionCommon.h>
#include <BulletCollision/CollisionShapes/btHeightfieldTerrainShape.h>

namespace sandpic {
namespace {

constexpr int kTileVertices = kTilePx * kGroundPerPx;  // + 1 shared with the next tile
constexpr float kHeadroom = 2;  // px of bounds above the highest vertex: fewer rebuilds

}  // namespace

Ground::Ground(int width, int height, Add add, Remove remove)
    : width_(width), height_(height), add_(std::move(add)), remove_(std::move(remove)) {
  tiles_.resize(size_t((width + kTilePx - 1) / kTilePx));
  for (Tile& t : tiles_) t.heights.assign(size_t(2 * (kTileVertices + 1)), 0.0f);
}

Ground::~Ground() {
  for (Tile& t : tiles_)
    if (t.object) remove_(t.object.get());
}

// A tile enters the world once raised above the floor (a solid box under
// it); its bounds, fixed when its shape is made, are remade when a vertex
// rises above them.
void Ground::rebuild(int i) {
  Tile& t = tiles_[size_t(i)];
  if (t.object) remove_(t.object.get());
  const float highest = *std::max_element(t.heights.begin(), t.heights.end());
  t.top = std::min(float(height_), highest + kHeadroom);
  t.shape = std::make_unique<btHeightfieldTerrainShape>(kTileVertices + 1, 2, t.heights.data(), btScalar(0),
                                                         btScalar(t.top), 1, false);
  t.shape->setLocalScaling(btVector3(btScalar(1.0 / kGroundPerPx), 1, 1));
  // Bullet centres a height field on its bounds.
  t.object = add_(t.shape.get(), Vec2(i * kTilePx + kTilePx / 2.0, t.top / 2.0));
}

void Ground::raise(Vec2 p, double r) {
  const int last = kGroundPerPx * width_;
  const int nearest = std::clamp(int(std::lround(p.x() * kGroundPerPx)), 0, last);
  const int from = std::clamp(int(std::ceil((p.x() - r) * kGroundPerPx)), 0, last);
  const int to = std::clamp(int(std::floor((p.x() + r) * kGroundPerPx)), 0, last);
  std::vector<int> grown;
  auto raise_vertex = [&](int v) {
    const double dx = double(v) / kGroundPerPx - p.x();
    const float top = float(std::min<double>(height_, p.y() + std::sqrt(std::max(0.0, r * r - dx * dx))));
    // A vertex on a tile's edge belongs to both tiles.
    for (int i : {v / kTileVertices - (v % kTileVertices == 0 ? 1 : 0), v / kTileVertices}) {
      if (i < 0 || i >= int(tiles_.size())) continue;
      Tile& t = tiles_[size_t(i)];
      const int local = v - i * kTileVertices;
      if (local > kTileVertices) continue;
      for (int row = 0; row < 2; ++row) {
        float& h = t.heights[size_t(row * (kTileVertices + 1) + local)];
        h = std::max(h, top);
      }
      if (top > t.top || !t.object) grown.push_back(i);
    }
  };
  for (int v = from; v <= to; ++v) raise_vertex(v);
  if (nearest < from || nearest > to) raise_vertex(nearest);
  std::sort(grown.begin(), grown.end());
  grown.erase(std::unique(grown.begin(), grown.end()), grown.end());
  for (int i : grown) rebuild(i);
}

}  // namespace sandpic
