#include "src/grain_table.h"

#include <algorithm>

#include <gtest/gtest.h>

#include "src/errors.h"
#include "src/init/init.h"
#include "src/pipeline.h"
#include "src/release.h"
#include "tests/test_util.h"

namespace sandpic {
namespace {

std::unique_ptr<Simulator> lattice_for(const Scene& s) { return make_simulator(s); }

TEST(GrainTable, EveryGrainOnceWithItsUnitOrderAndReleasePoint) {
  Scene s = test::one_ellipse_scene(200, 150, 40);
  s.segment.method = SegmentMethod::Ellipses;  // several units
  RunOptions opt;
  opt.grains = true;
  auto sim = lattice_for(s);
  const RunResult r = run_pipeline(s, *sim, opt);
  const std::vector<GrainRow> rows = parse_grain_table(r.grains, "t.csv");

  Initialization init = initialize(s);
  Segmentation seg = segment(s, init.tessellation);
  FallingOrder order = falling_order(seg, init.grains, s.layout());
  ASSERT_EQ(int64_t(rows.size()), r.stats["grains"]["total"].get<int64_t>());
  ASSERT_EQ(rows.size(), order.grain.size());
  const ReleaseModel model = release_model(s);
  std::vector<int> seen(order.grain.size(), 0);
  for (size_t i = 0; i < rows.size(); ++i) {
    const GrainRow& g = rows[i];
    if (i > 0) {
      EXPECT_GT(g.id, rows[i - 1].id);  // id order
    }
    EXPECT_EQ(g.cls, init.grains.cls[size_t(g.id)]);
    ASSERT_GE(g.order, 0);
    ASSERT_LT(size_t(g.order), order.grain.size());
    EXPECT_EQ(order.grain[size_t(g.order)], g.id);
    ++seen[size_t(g.order)];
    EXPECT_GE(g.order, order.unit_begin[size_t(g.unit)]);
    EXPECT_LT(g.order, order.unit_begin[size_t(g.unit) + 1]);
    // paper §7: its fall starts across its unit's outlet.
    const Outlet o = outlet(model, seg.units[size_t(g.unit)]);
    EXPECT_LE(std::abs(g.release_x - o.centre.x()), o.width / 2 + 0.001) << g.id;
    EXPECT_GE(g.x, 0);
    EXPECT_LE(g.x, s.window.width);
    EXPECT_GE(g.y, 0);
    EXPECT_LE(g.y, s.window.height);
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST(GrainTable, WithoutTheOptionNothingIsKept) {
  Scene s = test::one_ellipse_scene(120, 90, 20);
  auto sim = lattice_for(s);
  EXPECT_TRUE(run_pipeline(s, *sim, RunOptions{}).grains.empty());
}

TEST(GrainTable, BadTablesNameTheFileAndLine) {
  const std::string good = "id,class,unit,order,release_x,x,y\n0,1,0,3,1.500,2.000,3.250\n1,3,0,0,1.000,1.000,2.000\n";
  const std::vector<GrainRow> rows = parse_grain_table(good, "g.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].cls, 1);
  EXPECT_EQ(rows[0].order, 3);
  EXPECT_DOUBLE_EQ(rows[0].y, 3.25);
  for (const std::string& bad : {std::string("x,y\n0,1,0,3,1.5,2,3\n"),
                                 good + "2,7,0,1,1.0,1.0,1.0\n",      // no class 7
                                 good + "2,1,0,1,1.0,1.0\n",          // a field short
                                 good + "2,1,0,1,1.0,1.0,nan\n",      // not a number
                                 good + "2,1,0,1,1.0,1.0,1.0,9\n",    // one too many
                                 std::string("id,class,unit,order,release_x,x,y\n")}) {
    try {
      parse_grain_table(bad, "g.csv");
      ADD_FAILURE() << "accepted: " << bad;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("g.csv"), std::string::npos) << e.what();
    }
  }
  try {
    parse_grain_table(good + "2,7,0,1,1.0,1.0,1.0\n", "g.csv");
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("line 4"), std::string::npos) << e.what();
  }
}

#ifdef SANDPIC_WITH_BULLET
// paper §7: one release model for both backends, so their tables of one
// scene and physics seed compare grain by grain.
TEST(GrainTable, BothModesReleaseEachGrainAtTheSamePoint) {
  Scene s = test::one_ellipse_scene(60, 60, 6);  // 360 grains: a few seconds of DEM
  RunOptions opt;
  opt.grains = true;
  auto lattice = lattice_for(s);
  const std::vector<GrainRow> a = parse_grain_table(run_pipeline(s, *lattice, opt).grains, "lattice");
  s.mode = Mode::Dem;
  auto dem = make_simulator(s);
  const std::vector<GrainRow> b = parse_grain_table(run_pipeline(s, *dem, opt).grains, "dem");
  ASSERT_EQ(a.size(), b.size());
  double moved = 0;
  for (size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].id, b[i].id);
    EXPECT_EQ(a[i].release_x, b[i].release_x);
    moved += std::abs(a[i].x - b[i].x) + std::abs(a[i].y - b[i].y);
  }
  EXPECT_GT(moved, 0);  // two backends: not the same resting places
}
#endif

}  // namespace
}  // namespace sandpic
