#pragma once
// Helpers shared by the fuzz targets: the input as text, and a scratch file for parsers that read
// a path. One file per process (the pid in its name), so parallel fuzzers never share it.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <set>
#include <string>
#include <string_view>

namespace gcsim::fuzz {

inline std::string_view as_text(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The scratch files this process made, removed when it exits so runs leave nothing in /tmp.
struct ScratchFiles {
  std::set<std::string> paths;
  ~ScratchFiles() {
    for (const std::string& p : paths) std::remove(p.c_str());
  }
};

// Writes the input to a per-process scratch file with the given extension and returns its path.
inline std::string scratch_file(std::string_view text, const std::string& extension) {
  static ScratchFiles made;
  const std::string path = "/tmp/gcsim-fuzz-" + std::to_string(::getpid()) + extension;
  made.paths.insert(path);
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(text.data(), std::streamsize(text.size()));
  return path;
}

}  // namespace gcsim::fuzz
