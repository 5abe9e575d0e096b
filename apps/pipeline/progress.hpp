#pragma once
// A progress line for long commands: on a terminal (stderr is a tty) one line, rewritten in place
// at most ten times a second, with what is done and the wall time left; nothing at all when stderr
// is a file or a pipe, so logs and tests see only the results. GCSIM_PROGRESS=0 turns it off,
// =1 forces it on.
#include <chrono>
#include <optional>
#include <string>
#include <string_view>

namespace gcsim::pipeline {

class ProgressLine {
 public:
  // what: e.g. "sweep"; total: the number of steps (points, rows), or 0 when progress is given
  // as a fraction (update_fraction).
  ProgressLine(std::string what, int total);
  ~ProgressLine();  // clears the line
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  // done steps of total are finished; detail says what runs now (e.g. "running 64 nodes").
  void update(int done, std::string_view detail);
  // A fraction in [0, 1] of the work is done; detail e.g. "loop 120, 97.1% of the energy shot".
  void update_fraction(double fraction, std::string_view detail);
  // The same with the caller's own estimate of the wall seconds left (none: not shown), e.g. from
  // a plan's predictions (pass_progress.hpp) rather than from the pace so far.
  void update_fraction(double fraction, std::string_view detail, std::optional<double> seconds_left);
  // The work is done: the line shows 100 % once, with detail, and stays (a newline ends it).
  void finish(std::string_view detail);
  double elapsed_seconds() const;  // wall seconds since the line was made
  // Erases the line, before the command prints on stdout to the same terminal.
  void clear();
  bool shown() const { return enabled_; }

 private:
  void show(const std::string& done, std::string_view detail, std::optional<double> seconds_left);
  bool due();  // at most ten redraws a second
  bool finished_ = false;
  std::string what_;
  int total_;
  bool enabled_;
  std::chrono::steady_clock::time_point start_, last_;
};

// Whether progress is shown: GCSIM_PROGRESS if set, else isatty(stderr).
bool progress_wanted();

}  // namespace gcsim::pipeline
