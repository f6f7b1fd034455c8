// The studio's request functions, without HTTP.
#include "src/studio/api.h"

#include <filesystem>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "src/pipeline.h"
#include "src/scene_file.h"
#include "tests/test_folder.h"

namespace sandpic::studio {
namespace {

// The reply the server sends for what `f` throws.
template <class F>
Reply reply_of(F f) {
  try {
    return f();
  } catch (const InputError& e) {
    return error_reply(e.what());
  }
}

cv::Mat decode(const Reply& r) {
  return cv::imdecode(cv::Mat(1, int(r.body.size()), CV_8U, const_cast<char*>(r.body.data())), cv::IMREAD_COLOR);
}

TEST(StudioApi, ABadValueIsA400NamingItsKey) {
  const std::string root = test::fresh_folder("badkey");
  const Reply r = reply_of([&] { return preview(R"({"physics": {"friction": -1}})", root); });
  EXPECT_EQ(r.status, 400);
  const json body = json::parse(r.body);
  EXPECT_EQ(body["key"], "physics.friction");
  EXPECT_NE(body["error"].get<std::string>().find("scene key 'physics.friction'"), std::string::npos);
}

TEST(StudioApi, AnUnknownKeyIsNamedToo) {
  const Reply r = reply_of([&] { return preview(R"({"physics": {"frictoin": 0.4}})", "."); });
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(json::parse(r.body)["key"], "physics.frictoin");
}

TEST(StudioApi, MalformedJsonIsA400WithoutKey) {
  const Reply r = reply_of([&] { return preview("{\"physics\": ", "."); });
  EXPECT_EQ(r.status, 400);
  EXPECT_EQ(json::parse(r.body)["key"], "");
}

TEST(StudioApi, KeyOfTakesTheSceneKey) {
  EXPECT_EQ(key_of("scene file 'request': scene key 'region.height': must be in [1, 20000]"), "region.height");
  EXPECT_EQ(key_of("no key here"), "");
}

TEST(StudioApi, APreviewIsAPngOfTheWindowsSize) {
  const std::string root = test::fresh_folder("preview");
  const Reply r = preview("{}", root, 0.2);  // the default scene at 200 x 140
  EXPECT_EQ(r.status, 200);
  EXPECT_EQ(r.content_type, "image/png");
  const cv::Mat img = decode(r);
  ASSERT_FALSE(img.empty());
  EXPECT_EQ(img.cols, 200);
  EXPECT_EQ(img.rows, 140);
  const json stats = json::parse(r.headers.at("X-Sandpic-Stats"));
  EXPECT_EQ(stats["mode"], "lattice");
  EXPECT_EQ(stats["window"], json({200, 140}));
  // A palette PNG (IHDR colour type 3) of the render's pixels.
  ASSERT_GT(r.body.size(), 26u);
  EXPECT_EQ(r.body[25], 3);
  Scene s;
  apply_scale(s, 0.2);
  auto sim = make_simulator(s);
  const RunResult run = run_pipeline(s, *sim, {});
  EXPECT_EQ(cv::norm(img, run.picture, cv::NORM_INF), 0);
  EXPECT_GT(stats["timing"]["encode_s"].get<double>(), 0);
}

TEST(StudioApi, APreviewIsTheLatticesEvenForADemScene) {
  const Reply r = preview(R"({"mode": "dem"})", ".", 0.2);
  EXPECT_EQ(json::parse(r.headers.at("X-Sandpic-Stats"))["mode"], "lattice");
}

// While only physics changes, a preview reuses the last preview's layout and
// makes the bytes a fresh preview makes; a layout change prepares anew.
TEST(StudioApi, APhysicsOrColourChangeReusesTheLayout) {
  preview(R"({"seed": 4, "physics": {"friction": 0.3}})", ".", 0.2);
  const Reply dragged = preview(R"({"seed": 4, "physics": {"friction": 0.8}})", ".", 0.2);
  EXPECT_EQ(json::parse(dragged.headers.at("X-Sandpic-Stats"))["timing"]["layout_reused"], true);
  const Reply moved = preview(R"({"seed": 4, "segment": {"semi_major_min": 50}, "physics": {"friction": 0.8}})", ".", 0.2);
  EXPECT_FALSE(json::parse(moved.headers.at("X-Sandpic-Stats"))["timing"].contains("layout_reused"));
  preview(R"({"seed": 9})", ".", 0.2);  // another layout: the next one is fresh
  const Reply fresh = preview(R"({"seed": 4, "physics": {"friction": 0.8}})", ".", 0.2);
  EXPECT_FALSE(json::parse(fresh.headers.at("X-Sandpic-Stats"))["timing"].contains("layout_reused"));
  EXPECT_EQ(dragged.body, fresh.body);
  // The colours are the picture's alone: a new C1 keeps the layout too, and
  // its picture is the one a fresh preview of that scene makes.
  const std::string recoloured = R"({"seed": 4, "physics": {"friction": 0.8}, "grains": {"colors": ["#8a2f5d", "#b05030", "#e0b050", "#f5f0e6"]}})";
  const Reply c1 = preview(recoloured, ".", 0.2);
  EXPECT_EQ(json::parse(c1.headers.at("X-Sandpic-Stats"))["timing"]["layout_reused"], true);
  EXPECT_NE(c1.body, fresh.body);
  preview(R"({"seed": 9})", ".", 0.2);
  EXPECT_EQ(preview(recoloured, ".", 0.2).body, c1.body);
}

TEST(StudioApi, SameSceneAndSeedSameBytes) {
  const std::string body = R"({"seed": 7, "physics": {"friction": 0.6}})";
  const Reply a = preview(body, ".", 0.2), b = preview(body, ".", 0.2);
  EXPECT_EQ(a.body, b.body);
  const Reply c = preview(R"({"seed": 8, "physics": {"friction": 0.6}})", ".", 0.2);
  EXPECT_NE(a.body, c.body);
}

TEST(StudioApi, ARequestPastTheSizeBoundIsRefusedUnread) {
  const std::string body = "{\"description\": \"" + std::string(kMaxRequestBytes, 'x') + "\"}";
  try {
    scene_from_request(body, ".");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("over the limit"), std::string::npos) << e.what();
  }
}

TEST(StudioApi, PathsOutsideTheWorkingFolderAreRefused) {
  const std::string root = test::fresh_folder("paths");
  for (const char* body : {R"({"init": {"method": "halftone", "image": "../secret.png"}})",
                           R"({"init": {"image": "/etc/passwd"}})",
                           R"({"render": {"background": "a/../../b.png"}})"}) {
    const Reply r = reply_of([&] { return json_reply(to_json(scene_from_request(body, root))); });
    EXPECT_EQ(r.status, 400) << body;
    const json err = json::parse(r.body);
    EXPECT_NE(err["error"].get<std::string>().find("outside the studio's folder"), std::string::npos) << r.body;
    EXPECT_FALSE(err["key"].get<std::string>().empty()) << r.body;
  }
  EXPECT_NO_THROW(check_inside(root, "inputs/picture.png", "init.image"));
  EXPECT_THROW(check_inside(root, "../x.png", "init.image"), InputError);
}

TEST(StudioApi, TheScaleParameterIsChecked) {
  EXPECT_EQ(scale_param(""), 1);
  EXPECT_EQ(scale_param("0.5"), 0.5);
  for (const char* bad : {"0", "-1", "5", "abc", "0.5x", "nan"}) EXPECT_THROW(scale_param(bad), InputError) << bad;
}

TEST(StudioApi, UnitsAreTheSegmentationsEllipses) {
  const json u = json::parse(units("{}", ".").body);
  ASSERT_FALSE(u["ellipses"].empty());
  EXPECT_EQ(u["ellipses"][0].size(), 5u);
  EXPECT_TRUE(json::parse(units(R"({"segment": {"method": "cells"}})", ".").body)["ellipses"].empty());
}

TEST(StudioApi, ACompleteSceneHasEveryKey) {
  const json s = json::parse(complete_scene(R"({"physics": {"friction": 0.7}})", ".").body);
  EXPECT_EQ(s["physics"]["friction"], 0.7);
  EXPECT_EQ(s["window"]["width"], 1000);
}

// paper §3: the page paints cells by their number; the units list the
// scene's own cells in that numbering, with the classes an edit gave them.
TEST(StudioApi, UnitsListTheCellsWithTheirClasses) {
  const std::string root = test::fresh_folder("cells");
  const json plain = json::parse(units("{}", root).body);
  ASSERT_GT(plain["tessellation"].size(), 10u);
  for (const auto& c : plain["tessellation"]) {
    ASSERT_EQ(c.size(), 6u);
    EXPECT_LT(c[0].get<int>(), c[2].get<int>());
    EXPECT_LT(c[1].get<int>(), c[3].get<int>());
    EXPECT_NE(c[4], c[5]);  // dominant and secondary differ (Algorithm 1, line 4)
  }
  const json edited = json::parse(
      units(R"({"init": {"cell_overrides": [{"cell": 3, "dominant": 4, "secondary": 1}]}})", root).body);
  EXPECT_EQ(edited["tessellation"][3][4], 4);
  EXPECT_EQ(edited["tessellation"][3][5], 1);
  EXPECT_EQ(edited["tessellation"][2], plain["tessellation"][2]);  // the others are as drawn
  // The edit reaches the picture: the preview changes.
  EXPECT_NE(preview(R"({"init": {"cell_overrides": [{"cell": 3, "dominant": 4, "secondary": 1}]}})", root, 0.5).body,
            preview("{}", root, 0.5).body);
  // A cell past the tessellation's is named as the key.
  const Reply bad = reply_of([&] { return units(R"({"init": {"cell_overrides": [{"cell": 99999, "dominant": 1, "secondary": 2}]}})", root); });
  EXPECT_EQ(bad.status, 400);
  EXPECT_EQ(json::parse(bad.body)["key"], "init.cell_overrides");
}

TEST(StudioApi, OnlyLoopbackHostsAndTheStudiosOwnPage) {
  EXPECT_EQ(refusal("127.0.0.1", "GET", "127.0.0.1:8080", ""), "");
  EXPECT_EQ(refusal("127.0.0.1", "GET", "localhost:8080", ""), "");
  EXPECT_EQ(refusal("127.0.0.1", "GET", "[::1]:8080", ""), "");
  EXPECT_EQ(refusal("127.0.0.1", "GET", "", ""), "");  // HTTP/1.0: no Host, no browser
  // DNS rebinding: a name of another site resolved to 127.0.0.1.
  EXPECT_NE(refusal("127.0.0.1", "GET", "evil.example:8080", ""), "");
  EXPECT_NE(refusal("localhost", "GET", "127.0.0.1.evil.example", ""), "");
  // A page of another site posting to the studio.
  EXPECT_NE(refusal("127.0.0.1", "POST", "127.0.0.1:8080", "http://evil.example"), "");
  EXPECT_NE(refusal("127.0.0.1", "POST", "127.0.0.1:8080", "null"), "");
  EXPECT_EQ(refusal("127.0.0.1", "POST", "127.0.0.1:8080", "http://127.0.0.1:8080"), "");
  EXPECT_EQ(refusal("127.0.0.1", "GET", "127.0.0.1:8080", "http://evil.example"), "");  // a GET changes nothing
  // Told to listen elsewhere (--host): the designer chose to be reachable.
  EXPECT_EQ(refusal("0.0.0.0", "POST", "studio.lan:8080", "http://studio.lan:8080"), "");
}

// paper §4.2: a picture dropped on the page is kept in the studio's folder,
// named by its content, and a scene halftones it by that path.
TEST(StudioApi, APictureDroppedIsKeptAndHalftoned) {
  const std::string root = test::fresh_folder("image");
  cv::Mat img(60, 80, CV_8UC3);
  cv::randu(img, 0, 255);
  std::vector<uchar> jpg;
  cv::imencode(".jpg", img, jpg);
  const std::string bytes(jpg.begin(), jpg.end());
  const json up = json::parse(upload_image(bytes, root).body);
  const std::string path = up["path"];
  EXPECT_EQ(path.rfind("studio-inputs/image-", 0), 0u) << path;
  EXPECT_EQ(up["width"], 80);
  EXPECT_EQ(up["height"], 60);
  EXPECT_FALSE(cv::imread(root + "/" + path).empty());
  EXPECT_EQ(json::parse(upload_image(bytes, root).body)["path"], path);  // the same picture, the same file
  const Reply halftoned =
      preview(R"({"init": {"method": "halftone", "image": ")" + path + R"("}})", root, 0.2);
  EXPECT_EQ(halftoned.status, 200);
  EXPECT_NE(halftoned.body, preview("{}", root, 0.2).body);
  // Not a picture: a 400 that says so, and nothing kept.
  const Reply bad = reply_of([&] { return upload_image("not a picture at all", root); });
  EXPECT_EQ(bad.status, 400);
  EXPECT_NE(json::parse(bad.body)["error"].get<std::string>().find("image:"), std::string::npos);
  int files = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(root + "/studio-inputs")) ++files;
  EXPECT_EQ(files, 1);
  EXPECT_THROW(upload_image(std::string(kMaxImageBytes + 1, 'x'), root), TooLarge);
}

}  // namespace
}  // namespace sandpic::studio
