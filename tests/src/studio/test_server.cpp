// The studio's server on a free loopback port, spoken to over HTTP.
#include "src/studio/server.h"

#include <thread>

#include <gtest/gtest.h>
#include <httplib.h>
#include <nlohmann/json.hpp>

#include "src/scene_file.h"
#include "tests/test_folder.h"

namespace sandpic::studio {
namespace {

struct Running {
  Server server;
  int port;
  std::thread thread;
  explicit Running(const ServerOptions& opt) : server(opt), port(server.bind()), thread([this] { server.run(); }) {}
  ~Running() {
    server.stop();
    thread.join();
  }
};

ServerOptions options(const std::string& name) {
  ServerOptions opt;
  opt.port = 0;
  opt.root = test::fresh_folder(name);
  return opt;
}

TEST(StudioServer, ServesThePageAndPreviews) {
  Running s(options("server"));
  httplib::Client c("127.0.0.1", s.port);
  auto page = c.Get("/");
  ASSERT_TRUE(page);
  EXPECT_EQ(page->status, 200);
  EXPECT_NE(page->body.find("sandpic studio"), std::string::npos);
  for (const char* file : {"/app.js", "/sketch.js", "/scene.js", "/style.css"}) {
    auto r = c.Get(file);
    ASSERT_TRUE(r) << file;
    EXPECT_EQ(r->status, 200) << file;
  }
  auto png = c.Post("/api/preview?scale=0.2", "{}", "application/json");
  ASSERT_TRUE(png);
  EXPECT_EQ(png->status, 200);
  EXPECT_EQ(png->get_header_value("Content-Type"), "image/png");
  EXPECT_EQ(png->body.substr(1, 3), "PNG");
  EXPECT_TRUE(png->has_header("X-Sandpic-Stats"));
  auto keys = c.Get("/api/keys");
  ASSERT_TRUE(keys);
  EXPECT_EQ(keys->status, 200);
  EXPECT_EQ(nlohmann::json::parse(keys->body).size(), scene_fields().size());
}

TEST(StudioServer, ErrorsNameTheKeyAndUnknownPathsAre404) {
  Running s(options("errors"));
  httplib::Client c("127.0.0.1", s.port);
  auto bad = c.Post("/api/preview", R"({"region": {"height": -5}})", "application/json");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  EXPECT_EQ(nlohmann::json::parse(bad->body)["key"], "region.height");
  for (const char* path : {"/../CMakeLists.txt", "/%2e%2e/etc/passwd", "/api/render/99", "/nothing.js"}) {
    auto r = c.Get(path);
    ASSERT_TRUE(r) << path;
    EXPECT_EQ(r->status, 404) << path;
  }
  auto big = c.Post("/api/preview", std::string(2 << 20, ' '), "application/json");
  ASSERT_TRUE(big);
  EXPECT_EQ(big->status, 413);
}

TEST(StudioServer, AFinalRenderReportsItsProgressAndPicture) {
  Running s(options("render"));
  httplib::Client c("127.0.0.1", s.port);
  // The lattice mode: the route is the DEM's, the run a fraction of it.
  auto started = c.Post("/api/render?scale=0.2", R"({"mode": "lattice"})", "application/json");
  ASSERT_TRUE(started);
  ASSERT_EQ(started->status, 200) << started->body;
  const int id = nlohmann::json::parse(started->body)["id"];
  nlohmann::json st;
  for (int i = 0; i < 600; ++i) {
    st = nlohmann::json::parse(c.Get("/api/render/" + std::to_string(id))->body);
    if (st["done"]) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  ASSERT_EQ(st["done"], true) << st;
  EXPECT_EQ(st["error"], "");
  auto pic = c.Get("/api/render/" + std::to_string(id) + "/picture.png");
  ASSERT_TRUE(pic);
  EXPECT_EQ(pic->status, 200);
  EXPECT_EQ(pic->get_header_value("Content-Type"), "image/png");
}

TEST(StudioServer, TheFallCancelAndForeignRequests) {
  Running s(options("more"));
  httplib::Client c("127.0.0.1", s.port);
  auto fall = c.Post("/api/animation?scale=0.1&frames=3", "{}", "application/json");
  ASSERT_TRUE(fall);
  ASSERT_EQ(fall->status, 200) << fall->body;
  EXPECT_TRUE(fall->has_header("X-Sandpic-Frame-Sizes"));
  auto bad = c.Post("/api/animation?frames=0", "{}", "application/json");
  ASSERT_TRUE(bad);
  EXPECT_EQ(bad->status, 400);
  auto junk = c.Post("/api/image", "GIF89a but not really", "image/gif");
  ASSERT_TRUE(junk);
  EXPECT_EQ(junk->status, 400);
  auto none = c.Post("/api/render/77/cancel", "", "application/json");
  ASSERT_TRUE(none);
  EXPECT_EQ(none->status, 404);
  // DNS rebinding and other sites' pages.
  auto rebound = c.Get("/api/scene", {{"Host", "evil.example:" + std::to_string(s.port)}});
  ASSERT_TRUE(rebound);
  EXPECT_EQ(rebound->status, 403);
  auto posted = c.Post("/api/render", {{"Origin", "http://evil.example"}}, "{}", "application/json");
  ASSERT_TRUE(posted);
  EXPECT_EQ(posted->status, 403);
  auto own = c.Post("/api/units", {{"Origin", "http://127.0.0.1:" + std::to_string(s.port)}}, "{}", "application/json");
  ASSERT_TRUE(own);
  EXPECT_EQ(own->status, 200);
}

}  // namespace
}  // namespace sandpic::studio
