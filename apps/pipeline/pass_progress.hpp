#pragma once
// The progress of a command that runs passes one after the other, each with a predicted cost (for
// a render: `gcsim plan`'s estimate of each pass's time). The fraction done weighs each pass by its
// prediction; the time left is the predicted rest scaled by how the work done so far ran against
// its prediction (wall seconds per predicted second; the running pass's rest at its own pace). Pure arithmetic on the reports it is given
// (no clock, no terminal), so a test can drive it: the fraction never goes back, and reaches 1
// only when finish() says the last pass is done.
#include <optional>
#include <string>
#include <vector>

namespace gcsim::pipeline {

struct PassEstimate {
  std::string name;         // what the line calls it: "radiosity", "photons", "view (specular)"
  double predicted = 1.0;   // its predicted cost, in any unit the passes share (> 0)
};

struct PassProgressState {
  double fraction = 0.0;                // of the whole command, in [0, 1]
  std::string pass;                     // the pass running now (after finish: "done")
  int number = 0, of = 0;               // it is pass `number` of `of` (1-based)
  std::optional<double> seconds_left;   // once some work is done and until the end
};

class PassProgress {
 public:
  // The passes in the order they run; a prediction that is not positive and finite weighs as the
  // mean of the others (as 1 when none has one).
  explicit PassProgress(std::vector<PassEstimate> passes);

  // Pass `pass` (its index) has done `fraction` of its work, `elapsed` wall seconds after the
  // start. Reporting a later pass finishes the ones before it; a report for a pass already left
  // behind, or a smaller fraction, does not move the line back.
  PassProgressState report(int pass, double fraction, double elapsed);
  // Every pass is done: the one report of fraction 1.
  PassProgressState finish();

  const PassProgressState& state() const { return state_; }
  int passes() const { return int(passes_.size()); }

 private:
  std::vector<PassEstimate> passes_;
  double total_ = 0.0;
  int current_ = 0;
  double done_ = 0.0;  // predicted cost done so far, never decreasing
  double pass_start_ = 0.0;  // elapsed at the first report of the running pass
  PassProgressState state_;
};

}  // namespace gcsim::pipeline
