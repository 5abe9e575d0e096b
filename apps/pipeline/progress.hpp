#pragma once
// A progress line for long commands: on a terminal (stderr is a tty) one line, rewritten in place,
// with the steps done and the wall time left; nothing at all when stderr is a file or a pipe, so
// logs and tests see only the results. GCSIM_PROGRESS=0 turns it off, =1 forces it on.
#include <chrono>
#include <string>
#include <string_view>

namespace gcsim::pipeline {

class ProgressLine {
 public:
  // what: e.g. "sweep radiosity"; total: the number of steps (points, loops, rows).
  ProgressLine(std::string what, int total);
  ~ProgressLine();  // clears the line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // done steps of total are finished; detail says what the last one was (e.g. "64 nodes").
  void update(int done, std::string_view detail);
  // Erases the line, before the command prints on stdout to the same terminal.
  void clear();
  bool shown() const { return enabled_; }

 private:
  std::string what_;
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_;
};

// Whether progress is shown: GCSIM_PROGRESS if set, else isatty(stderr).
bool progress_wanted();

}  // namespace gcsim::pipeline
