#include "apps/pipeline/pass_progress.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gcsim::pipeline {

namespace {

// Below 1 until finish(): a pass that reports all its work done still has its end to run (the
// exchanges after the photons, the image assembled after the last tile).
constexpr double kBeforeEnd = 0.999;

}  // namespace

PassProgress::PassProgress(std::vector<PassEstimate> passes) : passes_(std::move(passes)) {
  if (passes_.empty()) throw std::invalid_argument("PassProgress: at least one pass");
  double known = 0.0;
  int with = 0;
  for (const PassEstimate& p : passes_)
    if (std::isfinite(p.predicted) && p.predicted > 0) known += p.predicted, ++with;
  const double fill = with > 0 ? known / with : 1.0;
  for (PassEstimate& p : passes_)
    if (!(std::isfinite(p.predicted) && p.predicted > 0)) p.predicted = fill;
  for (const PassEstimate& p : passes_) total_ += p.predicted;
  state_.pass = passes_.front().name;
  state_.number = 1;
  state_.of = int(passes_.size());
}

PassProgressState PassProgress::report(int pass, double fraction, double elapsed) {
  if (pass < 0 || pass >= passes()) throw std::out_of_range("PassProgress: no such pass");
  if (state_.fraction >= 1.0) return state_;  // finished: nothing moves any more
  if (pass > current_) current_ = pass, pass_start_ = elapsed;
  double before = 0.0;
  for (int i = 0; i < current_; ++i) before += passes_[std::size_t(i)].predicted;
  const double within = pass == current_ && std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) : 0.0;
  done_ = std::max(done_, before + within * passes_[std::size_t(current_)].predicted);
  state_.fraction = std::min(done_ / total_, kBeforeEnd);
  state_.pass = passes_[std::size_t(current_)].name;
  state_.number = current_ + 1;
  // Wall seconds per predicted unit so far, applied to what is predicted to remain; the running
  // pass's rest at its own pace once a tenth of it is done (passes miss their estimates differently).
  state_.seconds_left.reset();
  if (done_ <= 0 || elapsed <= 0) return state_;
  const double pace = elapsed / done_, predicted = passes_[std::size_t(current_)].predicted;
  const double in_pass = std::clamp(done_ - before, 0.0, predicted), after = total_ - before - predicted;
  const double own_pace = in_pass >= 0.1 * predicted ? (elapsed - pass_start_) / in_pass : pace;
  state_.seconds_left = std::max(0.0, own_pace * (predicted - in_pass) + pace * after);
  return state_;
}

PassProgressState PassProgress::finish() {
  current_ = passes() - 1;
  done_ = total_;
  state_.fraction = 1.0;
  state_.pass = "done";
  state_.number = passes();
  state_.seconds_left = 0.0;
  return state_;
}

}  // namespace gcsim::pipeline
