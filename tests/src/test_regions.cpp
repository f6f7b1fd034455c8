// paper §10, Fig. 17: areas of the region with their own settings.
#include <gtest/gtest.h>

#include <set>

#include "src/errors.h"
#include "src/init/init.h"
#include "src/regions.h"
#include "src/scene_file.h"
#include "src/segment/segment.h"

namespace sandpic {
namespace {

// Base: every grain S1. Area 0 (top band): every grain S4 in small cells under
// small ellipses; area 1 (a triangle lower down): S3.
Scene two_areas() {
  Scene s;
  s.window = {300, 200};
  s.region.height = 90;
  apply_json(s, json::parse(R"({
    "grains": {"proportions": [1, 0, 0, 0]}, "init": {"dominant_share": 1},
    "segment": {"semi_major_min": 40, "semi_major_max": 60},
    "regions": [
      {"rect": [0, 0, 300, 30], "grains": {"proportions": [0, 0, 0, 1]},
       "init": {"tessellation": "uniform", "cell_width": 10, "cell_height": 5},
       "segment": {"semi_major_min": 8, "semi_major_max": 12}},
      {"rect": [100, 20, 200, 90], "polygon": [[100, 90], [150, 20], [200, 90]],
       "grains": {"proportions": [0, 0, 1, 0]}}
    ]})"));
  return s;
}

TEST(Regions, FirstAreaListedWinsAndPolygonsHoldPixelCentres) {
  const Scene s = two_areas();
  const cv::Mat map = area_map(s);
  ASSERT_EQ(map.rows, 90);
  EXPECT_EQ(map.at<uint8_t>(25, 150), 1);  // in both: the first listed
  EXPECT_EQ(map.at<uint8_t>(60, 150), 2);  // inside the triangle
  EXPECT_EQ(map.at<uint8_t>(40, 110), 0);  // beside it: the scene's own
  EXPECT_EQ(map.at<uint8_t>(89, 101), 2);
  EXPECT_EQ(area_at(map, -5, 500), 0);     // clamped into the region
}

TEST(Regions, EachAreaIsFilledWithItsOwnColourMix) {
  const Scene s = two_areas();
  const Initialization init = initialize(s);
  const cv::Mat map = area_map(s);
  const int want[3] = {0, 3, 2};
  for (int y = 0; y < map.rows; ++y)
    for (int x = 0; x < map.cols; ++x)
      ASSERT_EQ(init.grains.cls[size_t(y) * 300 + x], want[map.at<uint8_t>(y, x)]) << x << "," << y;
  // The top area's own uniform cells, tagged and placed in window px.
  int own = 0;
  for (const Cell& c : init.tessellation.cells)
    if (c.area == 1) {
      ++own;
      EXPECT_EQ(c.x1 - c.x0, 10);
      EXPECT_LE(c.y1, 30);
    }
  EXPECT_EQ(own, 30 * 6);
}

TEST(Regions, GrainsFallOnlyWithUnitsOfTheirOwnArea) {
  const Scene s = two_areas();
  const Initialization init = initialize(s);
  const Segmentation seg = segment(s, init.tessellation);
  const cv::Mat map = area_map(s);
  std::set<int> areas;
  double small = 1e9, large = 0;
  for (const Unit& u : seg.units) {
    areas.insert(u.area);
    EXPECT_EQ(area_at(map, u.centre().x(), u.centre().y()), u.area);
    if (u.area == 1) small = std::min(small, u.ellipse.a);
    if (u.area == 0) large = std::max(large, u.ellipse.a);
  }
  EXPECT_EQ(areas, (std::set<int>{0, 1, 2}));
  EXPECT_LE(small, 12 * 1.15 + 1e-9);  // the top area's own small ellipses
  EXPECT_GE(large, 40);
  for (int y = 0; y < map.rows; ++y)
    for (int x = 0; x < map.cols; ++x)
      ASSERT_EQ(seg.units[size_t(seg.unit_of[size_t(y) * 300 + x])].area, map.at<uint8_t>(y, x)) << x << "," << y;
}

TEST(Regions, AnAreaSetsOnlyItsOwnKeysAndErrorsNameThePath) {
  Scene s;
  auto error_of = [&](const char* text) {
    try {
      apply_json(s, json::parse(text));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(error_of(R"({"regions": [{"grains": {"colors": ["#000000", "#000000", "#000000", "#000000"]}}]})")
                .find("regions[0].grains.colors"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"regions": [{}, {"segment": {"semi_major_min": -3}}]})").find("regions[1].segment.semi_major_min"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"regions": [{"segmnt": {}}]})").find("regions[0].segmnt"), std::string::npos);
  EXPECT_NE(error_of(R"({"regions": [{"rect": [5, 0, 5, 10]}]})").find("regions[0].rect"), std::string::npos);
  EXPECT_NE(error_of(R"({"regions": [{"preset": "moon"}]})").find("regions[0].preset"), std::string::npos);
  // A whole-scene check of an area's scene names the area too.
  Scene t;
  apply_json(t, json::parse(R"({"regions": [{"segment": {"semi_major_min": 90, "semi_major_max": 50}}]})"));
  try {
    validate(t);
    ADD_FAILURE() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("regions[0].segment.semi_major_min"), std::string::npos) << e.what();
  }
  // An area outside the region is refused by name.
  Scene u;
  apply_json(u, json::parse(R"({"regions": [{"rect": [0, 500, 100, 600]}]})"));
  EXPECT_THROW(area_map(u), InputError);
}

TEST(Regions, AnAreaPresetBringsOnlyItsInitSegmentAndProportions) {
  Scene s;
  apply_json(s, json::parse(R"({"regions": [{"preset": "clouds", "segment": {"semi_major_max": 40}}]})"));
  const Scene a = area_scene(s, 0);
  EXPECT_EQ(a.init.dominant_share, 0.95);      // the preset's
  EXPECT_EQ(a.segment.semi_major_max, 40);      // the area's own key over it
  EXPECT_EQ(a.grains.colors, s.grains.colors);  // colours stay the scene's
  EXPECT_EQ(a.grains.proportions[3], 0.42);
  EXPECT_NE(a.layout(), s.layout());            // its own layout
}

TEST(Regions, ScaleMovesAreasAndTheirLengths) {
  Scene s;
  apply_json(s, json::parse(
                    R"({"regions": [{"rect": [0, 0, 1000, 100], "polygon": [[0, 0], [10, 0], [0, 10]],
                        "segment": {"semi_major_min": 20, "eccentricity_max": 0.7}}]})"));
  apply_scale(s, 0.5);
  EXPECT_EQ(s.regions[0].rect[3], 50);
  EXPECT_EQ(s.regions[0].polygon[1][0], 5);
  const Scene a = area_scene(s, 0);
  EXPECT_EQ(a.segment.semi_major_min, 10);
  EXPECT_EQ(a.segment.eccentricity_max, 0.7);
  // Round trip through the scene's JSON.
  Scene back;
  apply_json(back, json::parse(to_json(s).dump()));
  EXPECT_EQ(to_json(back), to_json(s));
}

}  // namespace
}  // namespace sandpic
