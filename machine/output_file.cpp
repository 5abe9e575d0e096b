#include "machine/output_file.hpp"

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace gcsim::machine {

OutputFileError write_error(std::string_view what, const std::string& path, int err) {
  return OutputFileError(fmt::format("cannot write {} '{}': {}", what, path, std::strerror(err ? err : EIO)));
}

CheckedFile::~CheckedFile() {
  if (f_) std::fclose(f_);
}

void CheckedFile::open(const std::string& path, std::string_view what) {
  path_ = path;
  what_ = what;
  error_ = 0;
  f_ = std::fopen(path.c_str(), "wb");
  if (!f_) throw write_error(what_, path_, errno);
}

void CheckedFile::write(std::string_view bytes) {
  if (!f_ || error_) return;
  errno = 0;
  if (std::fwrite(bytes.data(), 1, bytes.size(), f_) != bytes.size() || std::fflush(f_) != 0) error_ = errno ? errno : EIO;
}

void CheckedFile::close() {
  if (!f_) return;
  errno = 0;
  const bool closed = std::fclose(f_) == 0;
  f_ = nullptr;
  if (!error_ && !closed) error_ = errno ? errno : EIO;
  if (error_) throw write_error(what_, path_, error_);
}

void write_text_file(const std::string& path, std::string_view text, std::string_view what) {
  CheckedFile f;
  f.open(path, what);
  f.write(text);
  f.close();
}

void close_checked(std::ofstream& out, const std::string& path, std::string_view what) {
  if (!out.is_open()) return;
  errno = 0;
  out.flush();
  const bool wrote = bool(out);
  const int err = errno;
  out.close();
  if (!wrote || !out) throw write_error(what, path, err ? err : errno);
}

}  // namespace gcsim::machine
