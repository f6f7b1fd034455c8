#pragma once
// A fresh, empty folder of the running test's own, named after the test: ctest
// runs tests in parallel, and a folder named after the suite alone was emptied
// by one test while its sibling wrote into it. (No process id in the name: the
// next run empties it again instead of leaving one more behind.)
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace sandpic::test {

inline std::string fresh_folder(const std::string& tag = "") {
  const auto* t = ::testing::UnitTest::GetInstance()->current_test_info();
  std::string name = "sandpic-test-";
  name += t ? std::string(t->test_suite_name()) + "." + t->name() : "no-test";
  if (!tag.empty()) name += "-" + tag;
  const auto dir = std::filesystem::temp_directory_path() / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace sandpic::test
