#pragma once
// stdout and stderr captured in memory without a system call per look: while it lives, the C
// streams stdout and stderr (and C++'s cout, cerr, clog over them) are fopencookie streams that
// append to a pending text, and write(2) on descriptors 1 and 2 (gcsim exports its own `write`,
// which the ranks' program copies and the libraries they call bind to) appends there too.
// Only what bypasses both (a child process, libc's dprintf) still reaches the descriptors.
#include <cstdio>
#include <memory>
#include <streambuf>
#include <string>

namespace gcsim::mpi_layer::app {

class CapturedStreams {
 public:
  CapturedStreams();
  ~CapturedStreams();  // restores the streams and write(2)
  CapturedStreams(const CapturedStreams&) = delete;
  CapturedStreams& operator=(const CapturedStreams&) = delete;

  // Flushes the streams; then pending(1) and pending(2) hold everything written since last taken.
  void flush();
  std::string& pending(int fd) { return fd == 1 ? out_ : err_; }
  void append(int fd, const char* data, std::size_t n) { pending(fd).append(data, n); }

 private:
  std::string out_, err_;
  FILE* saved_out_;
  FILE* saved_err_;
  FILE* cookie_out_;
  FILE* cookie_err_;
  std::streambuf* saved_bufs_[3];                  // cout, cerr, clog
  std::unique_ptr<std::streambuf> cookie_bufs_[3];  // theirs over the cookie streams
};

}  // namespace gcsim::mpi_layer::app
