#include "machine/max_min_solver.hpp"

#include <algorithm>
#include <utility>

namespace gcsim::machine {

MaxMinSolver::MaxMinSolver(int channels, double capacity)
    : capacity_(capacity),
      channels_(static_cast<std::size_t>(channels)) {}

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

void MaxMinSolver::Channel::add(int slot) {
  if (count < kNear) {
    near[static_cast<std::size_t>(count)] = slot;
  } else {
    far.push_back(slot);
  }
  ++count;
}

// The last flow takes the place of the one leaving.
void MaxMinSolver::Channel::remove(int slot) {
  int i = 0;
  while (flow(i) != slot) ++i;
  const int last = flow(count - 1);
  if (i < kNear) {
    near[static_cast<std::size_t>(i)] = last;
  } else {
    far[static_cast<std::size_t>(i - kNear)] = last;
  }
  if (count > kNear) far.pop_back();
  --count;
}

void MaxMinSolver::start(int slot) {
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  f.fresh = true;
  f.level = kNoLevel;
  for (int ch : f.route) channels_[static_cast<std::size_t>(ch)].add(slot);
  ++active_;
  const int group = join(slot);
  solve(group, f.route, slot, -1);
}

void MaxMinSolver::finish(int slot) {
  const Flow& f = flows_[static_cast<std::size_t>(slot)];
  // A channel's flows are a set: their order changes no rate (a level gives all it fixes the same
  // share, and a channel's capacity is given out level by level).
  for (int ch : f.route) channels_[static_cast<std::size_t>(ch)].remove(slot);
  --active_;
  solve(f.group, f.route, -1, slot);  // its level is dropped (its channel is perturbed): it leaves the solution
  leave(slot);
  free_slots_.push_back(slot);
}

void MaxMinSolver::solve(int group, const std::vector<int>& seed, int started, int finished) {
  ++solve_;
  group_ = &groups_[static_cast<std::size_t>(group)];
  const std::vector<Level>& last = group_->levels;
  live_.clear();
  touched_.clear();
  changed_.clear();
  next_levels_.clear();
  next_members_.clear();
  crossings_.clear();
  unsettled_.clear();
  if (started >= 0) unsettled_.push_back(started);
  finished_ = finished;
  best_ = -1;
  best_stale_ = false;
  for (int ch : seed) perturb(ch, 0);
  std::size_t k = 0;  // the next level of the last solution
  for (;;) {
    while (k < last.size() && channels_[static_cast<std::size_t>(last[k].channel)].perturbed == solve_)
      skip(k++);
    int best = -1;
    double best_share = 0;
    const bool any = tightest_perturbed(best, best_share);
    if (k < last.size()) {
      // Every unperturbed channel offers what it offered there, no less than this level's share.
      const Level& l = last[k];
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
void MaxMinSolver::perturb_now(int ch, std::size_t k) {
  Channel& c = channels_[static_cast<std::size_t>(ch)];
  c.perturbed = solve_;
  earlier_.clear();
  for (int i = 0; i < c.count; ++i) {
    const int s = c.flow(i);
    Flow& f = flows_[static_cast<std::size_t>(s)];
    if (f.level < static_cast<int>(k)) {
      earlier_.push_back(f.level);
      continue;
    }
    // Without a rate yet: a replay of its level must take its share here too.
    if (f.crossed != solve_) f.crossed = solve_, f.first_crossed = -1;
    crossings_.push_back({ch, f.first_crossed});
    f.first_crossed = static_cast<int>(crossings_.size() - 1);
  }
  // A few flows per channel: insertion sort.
  for (std::size_t i = 1; i < earlier_.size(); ++i)
    for (std::size_t j = i; j > 0 && earlier_[j] < earlier_[j - 1]; --j) std::swap(earlier_[j], earlier_[j - 1]);
  c.left = capacity_;
  for (int level : earlier_) c.left -= group_->levels[static_cast<std::size_t>(level)].share;
  c.unassigned = c.count - static_cast<int>(earlier_.size());
  // A channel with one flow only ever offers the whole capacity: left out, as settle() explains.
  if (c.count > 1 && c.unassigned > 0) {
    live_.push_back(ch);
    consider(ch);
  }
}

// Gives share to one more flow of perturbed channel ch.
void MaxMinSolver::take(int ch, double share) {
  Channel& c = channels_[static_cast<std::size_t>(ch)];
  c.left -= share;
  --c.unassigned;
  consider(ch);
}

// Keeps the tightest live channel up to date as perturbed channel ch changes or joins: only a
// change of that channel itself calls for a rescan (any other can only take its place).
void MaxMinSolver::consider(int ch) {
  if (best_stale_) return;
  if (ch == best_) {
    best_stale_ = true;
    return;
  }
  const Channel& c = channels_[static_cast<std::size_t>(ch)];
  if (c.unassigned == 0 || c.count < 2) return;
  offer(ch, c);
}

// Makes ch the tightest if it offers less than the tightest so far (or as much, lower-numbered).
// Most channels offer clearly more: a multiplication tells, and the division (whose rounding
// decides near ties) is left to the few that may not.
void MaxMinSolver::offer(int ch, const Channel& c) {
  if (best_ >= 0 && best_share_ > 0 && c.left > best_share_ * c.unassigned * (1 + 1e-9)) return;
  const double s = c.left / c.unassigned;
  if (best_ < 0 || s < best_share_ || (s == best_share_ && ch < best_)) best_ = ch, best_share_ = s;
}

// Level k of the last solution again: its channel is unperturbed, so its flows are the same and
// still without a rate, and its share is the same. Unperturbed channels change as they did then.
void MaxMinSolver::replay(std::size_t k) {
  const Level l = group_->levels[k];
  next_levels_.push_back({l.channel, l.share, static_cast<int>(next_members_.size()), l.count});
  for (int i = l.first; i < l.first + l.count; ++i) {
    const int s = group_->members[static_cast<std::size_t>(i)];
    next_members_.push_back(s);
    Flow& f = flows_[static_cast<std::size_t>(s)];
    f.fixed = solve_;
    f.new_rate = l.share;
    if (f.crossed != solve_) continue;
    for (int j = f.first_crossed; j >= 0; j = crossings_[static_cast<std::size_t>(j)].next)
      take(crossings_[static_cast<std::size_t>(j)].channel, l.share);
  }
}

// Level k of the last solution is not taken as it was: the channels its flows would have taken
// capacity from diverge from the last solution here.
void MaxMinSolver::skip(std::size_t k) {
  const Level& l = group_->levels[k];
  for (int i = l.first; i < l.first + l.count; ++i) {
    const int s = group_->members[static_cast<std::size_t>(i)];
    unsettled_.push_back(s);
    for (int ch : flows_[static_cast<std::size_t>(s)].route) perturb(ch, k);
  }
}

// A new level on a perturbed channel: its flows without a rate get the share, and every channel
// they cross is perturbed (the last solution did not take that capacity there).
void MaxMinSolver::fix(int ch, double share, std::size_t k) {
  next_levels_.push_back({ch, share, static_cast<int>(next_members_.size()), 0});
  int count = 0;
  const Channel& on = channels_[static_cast<std::size_t>(ch)];
  for (int i = 0; i < on.count; ++i) {
    const int s = on.flow(i);
    Flow& f = flows_[static_cast<std::size_t>(s)];
    if (f.fixed == solve_) continue;
    f.fixed = solve_;
    f.new_rate = share;
    touched_.push_back(s);
    next_members_.push_back(s);
    ++count;
    for (int c : f.route) {
      perturb(c, k);
      take(c, share);
    }
  }
  next_levels_.back().count = count;
}

// The perturbed channel offering the smallest share (the lowest-numbered on a tie), rescanned if
// stale; the scan drops the channels whose flows all have a rate.
bool MaxMinSolver::tightest_perturbed(int& best, double& best_share) {
  if (best_stale_) {
    best_stale_ = false;
    best_ = -1;
    std::size_t kept = 0;
    for (const int ch : live_) {
      const Channel& c = channels_[static_cast<std::size_t>(ch)];
      if (c.unassigned == 0) continue;
      live_[kept++] = ch;
      offer(ch, c);
    }
    live_.resize(kept);
  }
  best = best_;
  best_share = best_share_;
  return best_ >= 0;
}

// Flows still without a rate (only the new one and those of dropped levels can be: any other kept
// its level or had none) cross only channels of their own: every shared channel offered less than
// the capacity, so the filling would fix them last, each at left / 1 = the whole capacity.
// Then the new solution replaces the last, and the rates that moved are reported.
void MaxMinSolver::settle() {
  for (int s : unsettled_) {
    Flow& f = flows_[static_cast<std::size_t>(s)];
    if (f.fixed == solve_ || s == finished_) continue;
    f.fixed = solve_;
    f.new_rate = capacity_;
    f.level = kNoLevel;
    touched_.push_back(s);
  }
  for (std::size_t i = 0; i < next_levels_.size(); ++i) {
    const Level& l = next_levels_[i];
    for (int j = l.first; j < l.first + l.count; ++j)
      flows_[static_cast<std::size_t>(next_members_[static_cast<std::size_t>(j)])].level = static_cast<int>(i);
  }
  std::swap(group_->levels, next_levels_);
  std::swap(group_->members, next_members_);
  for (int s : touched_) {
    Flow& f = flows_[static_cast<std::size_t>(s)];
    if (f.fresh || f.new_rate != f.rate) changed_.push_back(s);
    f.rate = f.new_rate;
    f.fresh = false;
  }
}

}  // namespace gcsim::machine
