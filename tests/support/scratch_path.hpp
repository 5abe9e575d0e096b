#pragma once
// A path of its own under the system's temporary directory for a test's files. The process id in
// the name keeps concurrent test runs (two build trees or presets on one machine) from writing
// into, or removing, each other's files.
#include <unistd.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace gcsim::test_support {

inline std::filesystem::path scratch_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
}

// A fresh scratch folder for the running test (prefix + the test's name), removed when destroyed:
// a fixture member for tests whose files name each other.
class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix)
      : path_(scratch_path(prefix + ::testing::UnitTest::GetInstance()->current_test_info()->name())) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }
  // Writes text to name in the folder; returns the file's path.
  std::string write(const std::string& name, const std::string& text) const {
    std::ofstream(path_ / name) << text;
    return (path_ / name).string();
  }

 private:
  std::filesystem::path path_;
};

}  // namespace gcsim::test_support
