#include "machine/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <fmt/format.h>

namespace gcsim::machine {

namespace {

std::string kind_of(mode_t mode) {
  if (S_ISDIR(mode)) return "is a directory";
  if (S_ISCHR(mode) || S_ISBLK(mode)) return "is a device, not a file";
  if (S_ISFIFO(mode)) return "is a FIFO (named pipe), not a file";
  if (S_ISSOCK(mode)) return "is a socket, not a file";
  return "is not a regular file";
}

std::string size_text(std::uintmax_t bytes) {
  return bytes >= (1u << 20) ? fmt::format("{} MiB", bytes >> 20) : fmt::format("{} bytes", bytes);
}

}  // namespace

std::optional<std::string> why_not_regular_file(const std::filesystem::path& path) {
  struct stat st {};
  if (::stat(path.c_str(), &st) != 0)
    return errno == ENOENT ? std::string("does not exist") : std::string("cannot be read: ") + std::strerror(errno);
  if (!S_ISREG(st.st_mode)) return kind_of(st.st_mode);
  return std::nullopt;
}

InputFile read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  InputFile out;
  if (auto why = why_not_regular_file(path)) {
    out.error = *why;
    return out;
  }
  // O_NONBLOCK: should the path become a FIFO after the check, opening it does not wait.
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    out.error = std::string("cannot be opened: ") + std::strerror(errno);
    return out;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    out.error = kind_of(st.st_mode);
  } else if (std::uintmax_t(st.st_size) > max_bytes) {
    out.error = fmt::format("is {}, larger than the {} this kind of file may have", size_text(std::uintmax_t(st.st_size)),
                            size_text(max_bytes));
  } else {
    out.text.resize(std::size_t(st.st_size));
    std::size_t got = 0;
    while (got < out.text.size()) {
      const ssize_t n = ::read(fd, out.text.data() + got, out.text.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n < 0) {
        out.error = std::string("cannot be read: ") + std::strerror(errno);
        break;
      }
      if (n == 0) break;  // the file shrank while read: keep what is there
      got += std::size_t(n);
    }
    out.text.resize(got);
  }
  ::close(fd);
  if (!out.ok()) out.text.clear();
  return out;
}

}  // namespace gcsim::machine
