#pragma once
// What the dataset tests share: where the source tree's robots and scenarios are, a fresh
// scratch directory per test, and the check that bad input is one InputError line naming the
// file and the key.
#include <atomic>
#include <filesystem>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <unistd.h>

#include "wpg/datasets/input/input_error.hpp"
#include "../common/source_dir.hpp"

namespace wpg_test {

const std::string kSourceDir = sourceDir();
const std::string kRobotsDir = kSourceDir + "/robots";
const std::string kScenariosDir = kSourceDir + "/datasets/scenarios";

// A test that gets its own empty directory (below the system's temporary directory, named
// after `prefix`, the process and a counter), removed with everything in it afterwards.
class ScratchDirectoryTest : public ::testing::Test {
 protected:
  explicit ScratchDirectoryTest(std::string prefix) : prefix_(std::move(prefix)) {}

  void SetUp() override {
    static std::atomic<int> counter{0};
    directory_ = std::filesystem::temp_directory_path() /
                 (prefix_ + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override {
    std::error_code ec;
    std::filesystem::remove_all(directory_, ec);
  }

  std::filesystem::path directory_;

 private:
  std::string prefix_;
};

// `load` must throw one InputError line holding `file` and every one of `parts`.
inline void expectInputError(const std::function<void()>& load, const std::string& file,
                             std::initializer_list<std::string> parts) {
  try {
    load();
    ADD_FAILURE() << "no InputError for " << file;
  } catch (const wpg::datasets::InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(file), std::string::npos) << "file missing in: " << message;
    for (const std::string& part : parts) {
      EXPECT_NE(message.find(part), std::string::npos)
          << "'" << part << "' missing in: " << message;
    }
    EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
  }
}

}  // namespace wpg_test
