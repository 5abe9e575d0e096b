#include "machine/max_min_solver.hpp"

#include <algorithm>
#include <utility>

namespace gcsim::machine {

MaxMinSolver::MaxMinSolver(int channels, double capacity)
    : capacity_(capacity),
      on_channel_(static_cast<std::size_t>(channels)),
      perturbed_(static_cast<std::size_t>(channels), 0),
      left_(static_cast<std::size_t>(channels), 0.0),
      unassigned_(static_cast<std::size_t>(channels), 0) {}

int MaxMinSolver::open() {
  if (free_slots_.empty()) {
    flows_.emplace_back();
    return static_cast<int>(flows_.size() - 1);
  }
  const int slot = free_slots_.back();
  free_slots_.pop_back();
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  std::vector<int> route = std::move(f.route);  // keeps its storage for the new route
  route.clear();
  f = Flow{};
  f.route = std::move(route);
  return slot;
}

void MaxMinSolver::start(int slot) {
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  f.fresh = true;
  f.level = kNoLevel;
  for (int ch : f.route) on_channel_[static_cast<std::size_t>(ch)].push_back(slot);
  ++active_;
  solve(f.route);
}

void MaxMinSolver::finish(int slot) {
  const Flow& f = flows_[static_cast<std::size_t>(slot)];
  // A channel's flows are a set: their order changes no rate (see perturb and fix).
  for (int ch : f.route) {
    auto& v = on_channel_[static_cast<std::size_t>(ch)];
    *std::find(v.begin(), v.end(), slot) = v.back();
    v.pop_back();
  }
  --active_;
  solve(f.route);  // its old level is dropped (its channel is perturbed), so it leaves the solution
  free_slots_.push_back(slot);
}

void MaxMinSolver::solve(const std::vector<int>& seed) {
  ++solve_;
  perturbed_list_.clear();
  live_.clear();
  touched_.clear();
  changed_.clear();
  next_levels_.clear();
  next_members_.clear();
  for (int ch : seed) perturb(ch, 0);
  std::size_t k = 0;  // the next level of the last solution
  for (;;) {
    while (k < levels_.size() && perturbed_[static_cast<std::size_t>(levels_[k].channel)] == solve_) skip(k++);
    int best = -1;
    double best_share = 0;
    const bool any = tightest_perturbed(best, best_share);
    if (k < levels_.size()) {
      // Every unperturbed channel offers what it offered there, no less than this level's share.
      const Level& l = levels_[k];
      if (!any || l.share < best_share || (l.share == best_share && l.channel < best)) {
        replay(k++);
        continue;
      }
    } else if (!any) {
      break;
    }
    fix(best, best_share, k);
  }
  settle();
}

// Marks ch perturbed from here on, with the state it had before level k of the last solution (which
// it still has, being unperturbed so far): its capacity less the shares of its flows fixed by
// earlier levels, taken in level order as the filling did.
void MaxMinSolver::perturb(int ch, std::size_t k) {
  const auto c = static_cast<std::size_t>(ch);
  if (perturbed_[c] == solve_) return;
  perturbed_[c] = solve_;
  perturbed_list_.push_back(ch);
  const std::vector<int>& on = on_channel_[c];
  earlier_.clear();
  for (int s : on) {
    const int level = flows_[static_cast<std::size_t>(s)].level;
    if (level < static_cast<int>(k)) earlier_.push_back(level);
  }
  std::sort(earlier_.begin(), earlier_.end());
  double left = capacity_;
  for (int level : earlier_) left -= levels_[static_cast<std::size_t>(level)].share;
  left_[c] = left;
  unassigned_[c] = static_cast<int>(on.size() - earlier_.size());
  // A channel with one flow only ever offers the whole capacity: left out, as settle() explains.
  if (on.size() > 1 && unassigned_[c] > 0) live_.push_back(ch);
}

// Level k of the last solution again: its channel is unperturbed, so its flows are the same and
// still without a rate, and its share is the same.
void MaxMinSolver::replay(std::size_t k) {
  const Level l = levels_[k];
  next_levels_.push_back({l.channel, l.share, static_cast<int>(next_members_.size()), l.count});
  for (int i = l.first; i < l.first + l.count; ++i) {
    const int s = members_[static_cast<std::size_t>(i)];
    next_members_.push_back(s);
    Flow& f = flows_[static_cast<std::size_t>(s)];
    f.fixed = solve_;
    f.new_rate = l.share;
    for (int ch : f.route) {
      const auto c = static_cast<std::size_t>(ch);
      if (perturbed_[c] != solve_) continue;  // changes as it did last time
      left_[c] -= l.share;
      --unassigned_[c];
    }
  }
}

// Level k of the last solution is not taken as it was: the channels its flows would have taken
// capacity from diverge from the last solution here.
void MaxMinSolver::skip(std::size_t k) {
  const Level& l = levels_[k];
  for (int i = l.first; i < l.first + l.count; ++i)
    for (int ch : flows_[static_cast<std::size_t>(members_[static_cast<std::size_t>(i)])].route) perturb(ch, k);
}

// A new level on a perturbed channel: its flows without a rate get the share, and every channel
// they cross is perturbed (the last solution did not take that capacity there).
void MaxMinSolver::fix(int ch, double share, std::size_t k) {
  next_levels_.push_back({ch, share, static_cast<int>(next_members_.size()), 0});
  int count = 0;
  for (int s : on_channel_[static_cast<std::size_t>(ch)]) {
    Flow& f = flows_[static_cast<std::size_t>(s)];
    if (f.fixed == solve_) continue;
    f.fixed = solve_;
    f.new_rate = share;
    touched_.push_back(s);
    next_members_.push_back(s);
    ++count;
    for (int c : f.route) {
      perturb(c, k);
      left_[static_cast<std::size_t>(c)] -= share;
      --unassigned_[static_cast<std::size_t>(c)];
    }
  }
  next_levels_.back().count = count;
}

// The perturbed channel offering the smallest share (the lowest-numbered on a tie); drops the
// channels whose flows all have a rate.
bool MaxMinSolver::tightest_perturbed(int& best, double& best_share) {
  std::size_t kept = 0;
  for (const int ch : live_) {
    const auto c = static_cast<std::size_t>(ch);
    const int n = unassigned_[c];
    if (n == 0) continue;
    live_[kept++] = ch;
    const double share = left_[c] / n;
    if (best < 0 || share < best_share || (share == best_share && ch < best)) best = ch, best_share = share;
  }
  live_.resize(kept);
  return best >= 0;
}

// Flows still without a rate cross only channels of their own (every shared channel offered less
// than the capacity, so the filling would fix them last, each at left / 1 = the whole capacity).
// Then the new solution replaces the last, and the rates that moved are reported.
void MaxMinSolver::settle() {
  for (int ch : perturbed_list_) {
    for (int s : on_channel_[static_cast<std::size_t>(ch)]) {
      Flow& f = flows_[static_cast<std::size_t>(s)];
      if (f.fixed == solve_) continue;
      f.fixed = solve_;
      f.new_rate = capacity_;
      f.level = kNoLevel;
      touched_.push_back(s);
    }
  }
  for (std::size_t i = 0; i < next_levels_.size(); ++i) {
    const Level& l = next_levels_[i];
    for (int j = l.first; j < l.first + l.count; ++j)
      flows_[static_cast<std::size_t>(next_members_[static_cast<std::size_t>(j)])].level = static_cast<int>(i);
  }
  std::swap(levels_, next_levels_);
  std::swap(members_, next_members_);
  for (int s : touched_) {
    Flow& f = flows_[static_cast<std::size_t>(s)];
    if (f.fresh || f.new_rate != f.rate) changed_.push_back(s);
    f.rate = f.new_rate;
    f.fresh = false;
  }
}

}  // namespace gcsim::machine
