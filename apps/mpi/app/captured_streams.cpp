#include "apps/mpi/app/captured_streams.hpp"

#include <stdio_ext.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <ext/stdio_sync_filebuf.h>
#include <iostream>
#include <stdexcept>

namespace gcsim::mpi_layer::app {
namespace {

CapturedStreams* active = nullptr;

struct Target {
  CapturedStreams* streams;
  int fd;
};
Target out_target, err_target;

ssize_t append_cookie(void* cookie, const char* data, std::size_t n) {
  const auto* t = static_cast<const Target*>(cookie);
  t->streams->append(t->fd, data, n);
  return static_cast<ssize_t>(n);
}

FILE* open_cookie(Target& target, CapturedStreams* streams, int fd) {
  target = Target{streams, fd};
  cookie_io_functions_t io{};
  io.write = append_cookie;
  FILE* f = ::fopencookie(&target, "w", io);
  if (f == nullptr) throw std::runtime_error("gcsim mpirun: cannot capture the ranks' output (fopencookie failed)");
  // As the real streams on a memory file: stdout fully buffered in pages, stderr unbuffered, so a
  // rank's raw write(2)s and its printf()s interleave as they did with descriptors.
  if (fd == 1) {
    std::setvbuf(f, nullptr, _IOFBF, 4096);
  } else {
    std::setvbuf(f, nullptr, _IONBF, 0);
  }
  return f;
}

}  // namespace

CapturedStreams::CapturedStreams() : saved_out_(stdout), saved_err_(stderr) {
  std::fflush(stdout);
  std::fflush(stderr);
  std::cout.flush();
  std::cerr.flush();
  std::clog.flush();
  cookie_out_ = open_cookie(out_target, this, 1);
  cookie_err_ = open_cookie(err_target, this, 2);
  stdout = cookie_out_;
  stderr = cookie_err_;
  std::ostream* cxx[3] = {&std::cout, &std::cerr, &std::clog};
  for (int i = 0; i < 3; ++i) {
    cookie_bufs_[i] = std::make_unique<__gnu_cxx::stdio_sync_filebuf<char>>(i == 0 ? cookie_out_ : cookie_err_);
    saved_bufs_[i] = cxx[i]->rdbuf(cookie_bufs_[i].get());
  }
  active = this;
}

CapturedStreams::~CapturedStreams() {
  flush();
  active = nullptr;
  std::ostream* cxx[3] = {&std::cout, &std::cerr, &std::clog};
  for (int i = 0; i < 3; ++i) cxx[i]->rdbuf(saved_bufs_[i]);
  stdout = saved_out_;
  stderr = saved_err_;
  std::fclose(cookie_out_);
  std::fclose(cookie_err_);
}

void CapturedStreams::flush() {
  // Only a stream with buffered text is flushed: fflush takes the stream's lock even when empty.
  if (__fpending(cookie_out_) > 0) std::fflush(cookie_out_);
  if (__fpending(cookie_err_) > 0) std::fflush(cookie_err_);
}

}  // namespace gcsim::mpi_layer::app

// The ranks' raw write(2)s on descriptors 1 and 2 (exported: apps/mpi/CMakeLists.txt) join their
// stdio text in order; everything else is the system call unchanged.
extern "C" ssize_t write(int fd, const void* data, size_t n) {
  if (gcsim::mpi_layer::app::active != nullptr && (fd == 1 || fd == 2)) {
    gcsim::mpi_layer::app::active->append(fd, static_cast<const char*>(data), n);
    return static_cast<ssize_t>(n);
  }
  return ::syscall(SYS_write, fd, data, n);
}
