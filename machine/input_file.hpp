#pragma once
// The one way gcsim reads an input file: only a regular file (a directory, a device such as
// /dev/zero, a FIFO or a socket is named as such and refused before it is opened, so a read can
// neither block nor grow without end) and at most a size cap per format.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>

namespace gcsim::machine {

// Caps per format: far above any real file of the kind, far below host memory.
inline constexpr std::uintmax_t kMaxTomlFileBytes = 16u << 20;     // machine and scene files
inline constexpr std::uintmax_t kMaxMeshFileBytes = 1u << 30;       // OBJ, WORLD and entity files
inline constexpr std::uintmax_t kMaxDataFileBytes = 1u << 30;       // traces' CSV, run JSON

// An input file (a trace's CSV, a run JSON, ...) cannot be read or is malformed; the message
// names the file and, where there is one, the line. The command line maps it to exit status 3.
class InputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Why `path` cannot be read as an input file ("does not exist", "is a directory", "is a
// device", "is a FIFO", ...), or nothing when it is a regular file.
std::optional<std::string> why_not_regular_file(const std::filesystem::path& path);

// The whole file, or the reason it could not be read (not a regular file, larger than
// `max_bytes`, an I/O error with the system's reason). `error` is empty on success.
struct InputFile {
  std::string text;
  std::string error;
  bool ok() const { return error.empty(); }
};
InputFile read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes);

}  // namespace gcsim::machine
