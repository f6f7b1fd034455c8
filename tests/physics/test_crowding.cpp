#include <gtest/gtest.h>

#include "physics/crowding.h"

namespace sandpic {
namespace {

TEST(Crowding, AGrainInTheWayIsFoundAcrossCells) {
  Crowding c(20, 20);
  EXPECT_FALSE(c.crowded(Vec2(5, 5), 0.5));
  c.add(Vec2(3.9, 4.1), 0.5);  // another cell than (4.5, 4.1)
  EXPECT_TRUE(c.crowded(Vec2(4.5, 4.1), 0.3));   // centres 0.6 apart, radii 0.8
  EXPECT_FALSE(c.crowded(Vec2(4.85, 4.1), 0.3));  // 0.95 apart
  EXPECT_FALSE(c.crowded(Vec2(8, 8), 0.5));
  c.add(Vec2(19.9, 19.9), 0.5);  // at the window's corner
  EXPECT_TRUE(c.crowded(Vec2(19.5, 19.5), 0.5));
  c.clear();
  EXPECT_FALSE(c.crowded(Vec2(4.5, 4.1), 0.3));
  EXPECT_FALSE(c.crowded(Vec2(19.5, 19.5), 0.5));
}

}  // namespace
}  // namespace sandpic
