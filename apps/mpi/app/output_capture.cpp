#include "apps/mpi/app/output_capture.hpp"

#include <sys/mman.h>
#include <unistd.h>

#include <cstdio>
#include <stdexcept>
#include <string_view>

#include "parix/sim/fiber_stack.hpp"

namespace gcsim::mpi_layer::app {
namespace {

void write_all(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n <= 0) return;
    text.remove_prefix(static_cast<std::size_t>(n));
  }
}

}  // namespace

OutputCapture::OutputCapture(int ranks, bool tag_output)
    : outs_(static_cast<std::size_t>(ranks)), errs_(static_cast<std::size_t>(ranks)), tag_(tag_output) {
  std::fflush(stdout);
  std::fflush(stderr);
  for (Stream* s : {&out_, &err_}) {
    s->memory = ::memfd_create(s->fd == 1 ? "gcsim-mpirun-stdout" : "gcsim-mpirun-stderr", 0);
    s->saved = ::dup(s->fd);
    if (s->memory < 0 || s->saved < 0 || ::dup2(s->memory, s->fd) < 0) {
      throw std::runtime_error("gcsim mpirun: cannot capture the ranks' output (memfd_create/dup2 failed)");
    }
  }
  parix::report_stack_overflows_to(err_.saved);  // the run ends at once: the real stderr
  streams_.emplace();
}

OutputCapture::~OutputCapture() { finish(); }

void OutputCapture::drain(Stream& s, std::vector<std::string>& into, int rank) {
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::pread(s.memory, buffer, sizeof buffer, static_cast<off_t>(s.read));
    if (n <= 0) return;
    into[static_cast<std::size_t>(rank)].append(buffer, static_cast<std::size_t>(n));
    s.read += n;
  }
}

void OutputCapture::take_pending(int rank) {
  streams_->flush();
  for (int fd : {1, 2}) {
    std::string& pending = streams_->pending(fd);
    if (pending.empty()) continue;
    (fd == 1 ? outs_ : errs_)[static_cast<std::size_t>(rank)].append(pending);
    pending.clear();
  }
}

void OutputCapture::attribute(int rank) {
  if (!finished_) take_pending(rank);
}

void OutputCapture::print(const Stream& s, const std::vector<std::string>& texts, const char* name) const {
  for (std::size_t rank = 0; rank < texts.size(); ++rank) {
    std::string_view text = texts[rank];
    if (!tag_) {
      write_all(s.fd, text);
      continue;
    }
    const std::string tag = "[1," + std::to_string(rank) + "]<" + name + ">:";
    while (!text.empty()) {
      const std::size_t end = text.find('\n');
      const std::string_view line = text.substr(0, end == std::string_view::npos ? text.size() : end + 1);
      write_all(s.fd, tag);
      write_all(s.fd, line);
      if (line.back() != '\n') write_all(s.fd, "\n");
      text.remove_prefix(line.size());
    }
  }
}

void OutputCapture::finish() {
  if (finished_) return;
  take_pending(0);  // nothing, unless a rank printed after its last MPI call (see below)
  streams_.reset();
  std::fflush(stdout);
  std::fflush(stderr);
  finished_ = true;
  parix::report_stack_overflows_to(2);
  for (Stream* s : {&out_, &err_}) {
    ::dup2(s->saved, s->fd);
    ::close(s->saved);
  }
  // Anything not attributed yet (nothing, unless a rank printed after its last MPI call and the
  // run ended abnormally) goes to the last rank that ran: rank 0 by convention.
  for (Stream* s : {&out_, &err_}) {
    drain(*s, s->fd == 1 ? outs_ : errs_, 0);
    ::close(s->memory);
  }
  if (silent_) return;
  print(out_, outs_, "stdout");
  print(err_, errs_, "stderr");
}

}  // namespace gcsim::mpi_layer::app
