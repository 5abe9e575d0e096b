#pragma once
// A path of its own under the system's temporary directory for a test's files. The process id in
// the name keeps concurrent test runs (two build trees or presets on one machine) from writing
// into, or removing, each other's files.
#include <unistd.h>

#include <filesystem>
#include <string>

namespace gcsim::test_support {

inline std::filesystem::path scratch_path(const std::string& name) {
  return std::filesystem::temp_directory_path() / (name + "-" + std::to_string(::getpid()));
}

}  // namespace gcsim::test_support
