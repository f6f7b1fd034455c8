#pragma once
// A fresh empty folder for a studio test: its working folder, where renders go.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace sandpic::test {

inline std::string studio_folder(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("sandpic-studio-" + name + "-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

}  // namespace sandpic::test
