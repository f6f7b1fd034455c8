// The stress catalogue's judge: each promise it checks, broken once.
#include <filesystem>
#include <set>

#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "src/output.h"
#include "tests/test_folder.h"
#include "validate/stress/stress.h"

namespace sandpic {
namespace {

struct StressJudge : ::testing::Test {
  std::string dir;
  StressFiles f;
  StressCase c;

  void SetUp() override {
    dir = test::fresh_folder();
    f = {dir + "/picture.png", dir + "/stats.json", dir + "/stderr.txt", "old picture\n"};
    write_atomic(f.picture, f.sentinel);
    write_atomic(f.err, "");
    c.name = "case";
    c.expect = {Outcome::Picture, Outcome::Error, Outcome::Divergence};
  }
  void TearDown() override { std::filesystem::remove_all(dir); }

  // What a successful render leaves: a 40x30 picture and its stats.
  void rendered(int64_t released, int64_t in_picture, const std::string& extra = "") {
    cv::imwrite(f.picture, cv::Mat(30, 40, CV_8UC3, cv::Scalar(1, 2, 3)));
    write_atomic(f.stats, R"({"window": [40, 30], "grains": {"total": )" + std::to_string(released) +
                              R"(, "released": )" + std::to_string(released) + R"(, "in_picture": )" +
                              std::to_string(in_picture) + R"(}, "backend": {"deepest_overlap_px": 0.25,
                              "kinetic_energy_end_J": 1e-9, "substeps": 2)" + extra + "}}");
  }
  ChildRun exited(int code) {
    ChildRun r;
    r.exit_code = code;
    r.seconds = 0.5;
    return r;
  }
};

TEST_F(StressJudge, APictureWithEveryGrainIsAPicture) {
  rendered(100, 100);
  StressRow r = judge(c, "dem", exited(0), f);
  EXPECT_EQ(r.outcome, Outcome::Picture) << r.message;
  EXPECT_EQ(r.in_picture, 100);
  EXPECT_DOUBLE_EQ(r.overlap_px, 0.25);
  EXPECT_DOUBLE_EQ(r.kinetic_energy_j, 1e-9);
  EXPECT_EQ(r.substeps, 2);
}

TEST_F(StressJudge, AGrainMissingFails) {
  rendered(100, 99);
  EXPECT_EQ(judge(c, "dem", exited(0), f).outcome, Outcome::Fail);
}

TEST_F(StressJudge, ANaNInTheStatsFails) {
  rendered(100, 100, R"(, "speed": null)");
  StressRow r = judge(c, "dem", exited(0), f);
  EXPECT_EQ(r.outcome, Outcome::Fail);
  EXPECT_NE(r.message.find("NaN"), std::string::npos) << r.message;
}

TEST_F(StressJudge, APictureOfTheWrongSizeFails) {
  rendered(100, 100);
  cv::imwrite(f.picture, cv::Mat(31, 40, CV_8UC3, cv::Scalar(1, 2, 3)));
  EXPECT_EQ(judge(c, "dem", exited(0), f).outcome, Outcome::Fail);
}

TEST_F(StressJudge, AOneLineErrorIsAnError) {
  write_atomic(f.err, "sandpic: error: scene key 'region.height': bad\n");
  c.mention = "region.height";
  EXPECT_EQ(judge(c, "lattice", exited(2), f).outcome, Outcome::Error);
  EXPECT_EQ(judge(c, "lattice", exited(3), f).outcome, Outcome::Divergence);
}

TEST_F(StressJudge, AnErrorThatDoesNotNameTheKeyFails) {
  write_atomic(f.err, "sandpic: error: something is wrong\n");
  c.mention = "region.height";
  EXPECT_EQ(judge(c, "lattice", exited(2), f).outcome, Outcome::Fail);
}

TEST_F(StressJudge, TwoLinesOnStderrFail) {
  write_atomic(f.err, "libpng warning: oops\nsandpic: error: bad\n");
  EXPECT_EQ(judge(c, "lattice", exited(2), f).outcome, Outcome::Fail);
}

TEST_F(StressJudge, AFailedRunThatTouchedTheOldPictureFails) {
  write_atomic(f.err, "sandpic: error: bad\n");
  write_atomic(f.picture, "half a picture");
  EXPECT_EQ(judge(c, "lattice", exited(2), f).outcome, Outcome::Fail);
}

TEST_F(StressJudge, AFailedRunThatWroteStatsFails) {
  write_atomic(f.err, "sandpic: simulation failed: diverged\n");
  write_atomic(f.stats, "{}");
  EXPECT_EQ(judge(c, "dem", exited(3), f).outcome, Outcome::Fail);
}

TEST_F(StressJudge, CrashesHangsAndOtherCodesFail) {
  ChildRun crash = exited(-1);
  crash.signal = 11;
  EXPECT_EQ(judge(c, "dem", crash, f).outcome, Outcome::Fail);
  ChildRun hang = exited(-1);
  hang.timed_out = true;
  EXPECT_EQ(judge(c, "dem", hang, f).outcome, Outcome::Fail);
  EXPECT_EQ(judge(c, "dem", exited(1), f).outcome, Outcome::Fail);
}

TEST_F(StressJudge, AnOutcomeNotExpectedFails) {
  rendered(100, 100);
  c.expect = {Outcome::Error};
  StressRow r = judge(c, "lattice", exited(0), f);
  EXPECT_EQ(r.outcome, Outcome::Fail);
  EXPECT_NE(r.message.find("expected"), std::string::npos) << r.message;
}

TEST_F(StressJudge, ChildRunsReportExitCodesSignalsAndHangs) {
  const std::string out = dir + "/out.txt", err = dir + "/err.txt";
  EXPECT_EQ(run_child({"/bin/sh", "-c", "echo hi >&2; exit 3"}, out, err, 10).exit_code, 3);
  EXPECT_EQ(read_text(err).value_or(""), "hi\n");
  EXPECT_EQ(run_child({"/bin/sh", "-c", "kill -SEGV $$"}, out, err, 10).signal, 11);
  ChildRun hang = run_child({"/bin/sh", "-c", "sleep 20"}, out, err, 0.2);
  EXPECT_TRUE(hang.timed_out);
  EXPECT_LT(hang.seconds, 10);
}

TEST(StressCases, TheIssuesCasesAreAllThereWithUniqueNames) {
  std::set<std::string> names;
  for (const StressCase& c : stress_cases(true)) {
    EXPECT_TRUE(names.insert(c.name).second) << c.name;
    EXPECT_FALSE(c.modes.empty()) << c.name;
    EXPECT_FALSE(c.expect.empty()) << c.name;
  }
  for (const char* n : {"friction-0", "friction-1.5", "restitution-0", "restitution-1", "grains-0.01mm", "grains-5mm",
                        "density-100:1", "step-x10", "step-x20-no-substeps", "step-div10", "millions", "region-1px", "region-full", "region-full-fine",
                        "eccentricity-0", "eccentricity-0.999", "ellipses-overlapping", "ellipses-outside", "image-1x1",
                        "image-16bit", "image-grey", "image-alpha", "image-wrong-size", "json-malformed", "json-nan"})
    EXPECT_TRUE(names.count(n)) << n;
}

}  // namespace
}  // namespace sandpic
