// Final renders in the background: one at a time, status with a fraction,
// and the finished picture kept on disk.
#include "src/studio/renders.h"

#include <chrono>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "src/errors.h"
#include "src/studio/api.h"
#include "tests/test_folder.h"

namespace sandpic::studio {
namespace {

// Up to 5 minutes: a guard against a hang, not a timing (a sanitizer build
// on a loaded machine takes a minute for the DEM render below).
std::shared_ptr<const RenderJob> wait_done(const Renders& r, int id) {
  for (int i = 0; i < 30000; ++i) {
    auto job = r.job(id);
    if (job->done) return job;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return nullptr;
}

// The studio never runs another program: a scene in mode lammps is refused
// at once, naming the key, and nothing is started or written.
TEST(StudioRenders, TheLammpsModeIsRefused) {
  const std::string dir = test::fresh_folder("renders-lammps") + "/studio-renders";
  Renders renders(dir);
  Scene s = scaled(scene_from_request("{}", "."), 0.2);
  s.mode = Mode::Lammps;
  try {
    renders.start(s);
    FAIL() << "a lammps render started";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mode"), std::string::npos) << e.what();
  }
  EXPECT_FALSE(std::filesystem::exists(dir));
}

TEST(StudioRenders, AFinishedRenderIsKeptOnDisk) {
  const std::string dir = test::fresh_folder("renders") + "/studio-renders";
  Renders renders(dir);
  // The lattice mode: the same path as the DEM's, in a fraction of the time.
  const int id = renders.start(scaled(scene_from_request("{}", "."), 0.2));
  auto job = wait_done(renders, id);
  ASSERT_TRUE(job);
  EXPECT_EQ(job->error, "");
  EXPECT_TRUE(std::filesystem::is_regular_file(job->picture)) << job->picture;
  const ordered_json st = status_json(*job);
  EXPECT_EQ(st["done"], true);
  EXPECT_EQ(st["fraction"], 1.0);
  // The scene and stats beside it, and no temporary file left.
  int files = 0;
  for (const auto& e : std::filesystem::directory_iterator(dir)) {
    ++files;
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
  EXPECT_EQ(files, 3);
  EXPECT_EQ(renders.job(id + 1), nullptr);
}

TEST(StudioRenders, OneAtATime) {
  Renders renders(test::fresh_folder("one") + "/r");
  const Scene s = scene_from_request("{}", ".");  // full size: long enough to overlap
  const int id = renders.start(s);
  EXPECT_THROW(renders.start(s), Busy);
  ASSERT_TRUE(wait_done(renders, id));
  EXPECT_NO_THROW(wait_done(renders, renders.start(scaled(s, 0.2))));
}

TEST(StudioRenders, TheDemModeNeedsBullet) {
  Renders renders(test::fresh_folder("dem") + "/r");
  const Scene s = scene_from_request(R"({"mode": "dem"})", ".");
#if SANDPIC_WITH_BULLET
  // This build has the DEM: a small final render finishes with every grain.
  auto job = wait_done(renders, renders.start(scaled(s, 0.0845)));
  ASSERT_TRUE(job);
  EXPECT_EQ(job->error, "");
  EXPECT_TRUE(std::filesystem::is_regular_file(job->picture)) << job->picture;
#else
  try {
    renders.start(s);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(key_of(e.what()), "mode");
  }
#endif
}

// The page's cancel button: the render stops within a step cycle, says so,
// writes nothing, and the next one may start.
TEST(StudioRenders, ACancelledRenderStopsAndWritesNothing) {
  const std::string dir = test::fresh_folder("cancel") + "/r";
  Renders renders(dir);
  EXPECT_FALSE(renders.cancel(1));  // no such render
#if SANDPIC_WITH_BULLET
  const Scene s = scaled(scene_from_request(R"({"mode": "dem"})", "."), 0.3);  // half an hour if left to run
#else
  const Scene s = scene_from_request("{}", ".");
#endif
  const int id = renders.start(s);
#if SANDPIC_WITH_BULLET
  // Well into the fall, so the stop comes from inside the step loop.
  for (int i = 0; i < 3000 && renders.job(id)->fraction == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  EXPECT_GT(renders.job(id)->fraction, 0);
#endif
  const bool stopping = renders.cancel(id);
  auto job = wait_done(renders, id);
  ASSERT_TRUE(job);
#if SANDPIC_WITH_BULLET
  ASSERT_TRUE(stopping);
#endif
  if (stopping && job->cancelled) {  // the lattice may have finished first
    EXPECT_EQ(job->error, "cancelled");
    EXPECT_EQ(job->picture, "");
    EXPECT_EQ(status_json(*job)["cancelled"], true);
    EXPECT_TRUE(std::filesystem::is_empty(dir));
  }
  EXPECT_FALSE(renders.cancel(id));  // done already
  auto next = wait_done(renders, renders.start(scaled(scene_from_request("{}", "."), 0.2)));
  ASSERT_TRUE(next);
  EXPECT_EQ(next->error, "");
  EXPECT_FALSE(next->cancelled);
}

}  // namespace
}  // namespace sandpic::studio
