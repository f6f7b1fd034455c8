#include "physics/crowding.h"

#include <algorithm>
#include <cmath>

namespace sandpic {

Crowding::Crowding(int width, int height)
    : cells_x_(int(std::ceil(width / kCell)) + 1),
      cells_y_(int(std::ceil(height / kCell)) + 1),
      head_(size_t(cells_x_) * size_t(cells_y_), -1) {}

void Crowding::clear() {
  std::fill(head_.begin(), head_.end(), -1);
  next_.clear();
  pos_.clear();
  radius_.clear();
}

int Crowding::cell_of(Vec2 p) const {
  const int cx = int(std::floor(p.x() / kCell)), cy = int(std::floor(p.y() / kCell));
  if (cx < 0 || cy < 0 || cx >= cells_x_ || cy >= cells_y_) return -1;
  return cy * cells_x_ + cx;
}

void Crowding::add(Vec2 p, double r) {
  const int c = cell_of(p);
  next_.push_back(c >= 0 ? head_[size_t(c)] : -1);
  if (c >= 0) head_[size_t(c)] = int32_t(pos_.size());
  pos_.push_back(p);
  radius_.push_back(r);
}

bool Crowding::crowded(Vec2 p, double r) const {
  const int cx = int(std::floor(p.x() / kCell)), cy = int(std::floor(p.y() / kCell));
  for (int y = std::max(0, cy - 1); y <= std::min(cells_y_ - 1, cy + 1); ++y)
    for (int x = std::max(0, cx - 1); x <= std::min(cells_x_ - 1, cx + 1); ++x)
      for (int32_t i = head_[size_t(y * cells_x_ + x)]; i >= 0; i = next_[size_t(i)]) {
        const double reach = r + radius_[size_t(i)];
        if ((pos_[size_t(i)] - p).squaredNorm() < reach * reach) return true;
      }
  return false;
}

}  // namespace sandpic
