#pragma once
// The ranks' stdout and stderr, kept apart. All ranks share one host process and so one stdout;
// while they run, their streams and write(2)s append in memory (captured_streams.hpp), and whatever
// appeared there since the last look belongs to the rank that ran meanwhile (ranks switch only
// inside MPI calls, which look first). File descriptors 1 and 2 go to memory files meanwhile, for
// what bypasses the streams (a child process's output): it is read once, when the run ends. When the run ends, each rank's output is printed in rank order, stdout to stdout and
// stderr to stderr, each line prefixed "[1,RANK]<stdout>:" with --tag-output, as Open MPI does.
#include <optional>
#include <string>
#include <vector>

#include "apps/mpi/app/captured_streams.hpp"

namespace gcsim::mpi_layer::app {

class OutputCapture {
 public:
  OutputCapture(int ranks, bool tag_output);
  ~OutputCapture();  // restores the descriptors and prints what is left
  OutputCapture(const OutputCapture&) = delete;
  OutputCapture& operator=(const OutputCapture&) = delete;

  // What appeared since the last call is rank's.
  void attribute(int rank);
  // Restores stdout and stderr and prints every rank's output; later calls do nothing.
  void finish();
  // Keeps the output instead of printing it at finish() (a sweep's points): each rank's stderr
  // stays readable for a failure's message.
  void keep_silent() { silent_ = true; }
  const std::string& stderr_of(int rank) const { return errs_[static_cast<std::size_t>(rank)]; }

 private:
  struct Stream {
    int fd;          // 1 or 2
    int saved = -1;  // the real descriptor
    int memory = -1;
    long long read = 0;  // bytes of the memory file attributed so far
  };
  void drain(Stream& s, std::vector<std::string>& into, int rank);
  void take_pending(int rank);
  void print(const Stream& s, const std::vector<std::string>& texts, const char* name) const;
  Stream out_{1}, err_{2};
  std::optional<CapturedStreams> streams_;
  std::vector<std::string> outs_, errs_;
  bool tag_;
  bool finished_ = false;
  bool silent_ = false;
};

}  // namespace gcsim::mpi_layer::app
