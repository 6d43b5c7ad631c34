// A fixture that gives each test a fresh folder of its own in the temporary directory, named after the test suite,
// the process and the test, and removes it afterwards.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <string>

namespace skinlayer::test {

class ScratchFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::string name =
        "skinlayer_" + std::string(info->test_suite_name()) + "_" + std::to_string(::getpid()) + "_" + info->name();
    std::replace(name.begin(), name.end(), '/', '_');  // parameterized tests: "Suite/Test.Case/param"
    dir_ = std::filesystem::temp_directory_path() / name;
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // The path of a file in the folder.
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  std::filesystem::path dir_;
};

}  // namespace skinlayer::test
