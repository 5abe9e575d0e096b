#pragma once
// Output files whose every write and close are checked: a full disk (or /dev/full) is an error
// naming the file and the system's reason, never a silent exit 0 with a truncated file.
#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>

namespace gcsim::machine {

// An output file cannot be written; the command line maps it to exit status 3.
class OutputFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// "cannot write WHAT 'PATH': REASON" for the system error `err` (an errno value).
OutputFileError write_error(std::string_view what, const std::string& path, int err);

// A C stream that keeps its first write error; close() reports it (and the close's own).
class CheckedFile {
 public:
  CheckedFile() = default;
  CheckedFile(const CheckedFile&) = delete;
  CheckedFile& operator=(const CheckedFile&) = delete;
  ~CheckedFile();  // closes without throwing; call close() on the normal path

  // Opens (truncates) `path`; throws OutputFileError. `what` names it in errors ("trace file").
  void open(const std::string& path, std::string_view what);
  bool is_open() const { return f_ != nullptr; }
  // Writes and flushes; after a failure further writes are skipped and the error is kept.
  void write(std::string_view bytes);
  bool failed() const { return error_ != 0; }
  // Closes; throws OutputFileError for the first write error or the close's.
  void close();

 private:
  std::FILE* f_ = nullptr;
  std::string path_, what_;
  int error_ = 0;
};

// Writes `text` to `path` (replacing it); throws OutputFileError naming `what` and the reason.
void write_text_file(const std::string& path, std::string_view text, std::string_view what);

// Flushes and closes an ofstream a writer filled; throws OutputFileError when a write or the close failed.
void close_checked(std::ofstream& out, const std::string& path, std::string_view what);

}  // namespace gcsim::machine
