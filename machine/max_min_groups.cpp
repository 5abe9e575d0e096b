// MaxMinSolver's groups: each keeps the levels of its flows' last solution, so that a solve replays
// the levels of the flows it can affect and no others.
#include <utility>

#include "machine/max_min_solver.hpp"

namespace gcsim::machine {

// The group of a starting flow (already on its channels): the groups of the flows it shares a
// channel with, merged into the one with the most levels, or a new group if it shares none.
int MaxMinSolver::join(int slot) {
  ++joins_;
  joined_.clear();
  for (int ch : flows_[static_cast<std::size_t>(slot)].route) {
    const Channel& c = channels_[static_cast<std::size_t>(ch)];
    for (int i = 0; i < c.count; ++i) {
      const int s = c.flow(i);
      if (s == slot) continue;
      const int g = flows_[static_cast<std::size_t>(s)].group;
      if (groups_[static_cast<std::size_t>(g)].seen == joins_) continue;
      groups_[static_cast<std::size_t>(g)].seen = joins_;
      joined_.push_back(g);
    }
  }
  int into;
  if (joined_.empty()) {
    if (free_groups_.empty()) {
      groups_.emplace_back();
      into = static_cast<int>(groups_.size() - 1);
    } else {
      into = free_groups_.back();
      free_groups_.pop_back();
    }
  } else {
    into = joined_.front();
    for (int g : joined_)
      if (groups_[static_cast<std::size_t>(g)].levels.size() > groups_[static_cast<std::size_t>(into)].levels.size()) into = g;
    for (int g : joined_)
      if (g != into) merge(into, g);
  }
  Group& g = groups_[static_cast<std::size_t>(into)];
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  f.group = into;
  f.in_group = static_cast<int>(g.flows.size());
  g.flows.push_back(slot);
  return into;
}

// Group `from` joins `into`. Their flows shared no channel, so solved together their levels
// interleave: each step takes the head that offers less (the lower channel on a tie), which is what
// progressive filling over both would have chosen.
void MaxMinSolver::merge(int into, int from) {
  Group& a = groups_[static_cast<std::size_t>(into)];
  Group& b = groups_[static_cast<std::size_t>(from)];
  next_levels_.clear();
  next_members_.clear();
  std::size_t i = 0, j = 0;
  while (i < a.levels.size() || j < b.levels.size()) {
    const bool from_a = j == b.levels.size() ||
                        (i < a.levels.size() && (a.levels[i].share < b.levels[j].share ||
                                                 (a.levels[i].share == b.levels[j].share && a.levels[i].channel < b.levels[j].channel)));
    const Group& g = from_a ? a : b;
    const Level l = from_a ? a.levels[i++] : b.levels[j++];
    const auto index = static_cast<int>(next_levels_.size());
    next_levels_.push_back({l.channel, l.share, static_cast<int>(next_members_.size()), l.count});
    for (int m = l.first; m < l.first + l.count; ++m) {
      const int s = g.members[static_cast<std::size_t>(m)];
      next_members_.push_back(s);
      flows_[static_cast<std::size_t>(s)].level = index;
    }
  }
  std::swap(a.levels, next_levels_);
  std::swap(a.members, next_members_);
  for (int s : b.flows) {
    Flow& f = flows_[static_cast<std::size_t>(s)];
    f.group = into;
    f.in_group = static_cast<int>(a.flows.size());
    a.flows.push_back(s);
  }
  b.levels.clear();
  b.members.clear();
  b.flows.clear();
  b.ends = 0;
  free_groups_.push_back(from);
}

// A flow that ended (and was solved away) leaves its group; an empty group is free for reuse.
void MaxMinSolver::leave(int slot) {
  Flow& f = flows_[static_cast<std::size_t>(slot)];
  Group& g = groups_[static_cast<std::size_t>(f.group)];
  const int last = g.flows.back();
  g.flows[static_cast<std::size_t>(f.in_group)] = last;
  flows_[static_cast<std::size_t>(last)].in_group = f.in_group;
  g.flows.pop_back();
  const int group = f.group;
  f.group = f.in_group = -1;
  if (g.flows.empty()) {
    g.levels.clear();
    g.members.clear();
    g.ends = 0;
    free_groups_.push_back(group);
  } else if (++g.ends >= g.flows.size()) {
    split(group);  // as often as the group's size allows, so that it costs a few steps per end
  }
}

// Labels the group's flows with their connected component (`part`, from 0); returns how many.
int MaxMinSolver::mark_parts(const Group& g) {
  ++splits_;
  int parts = 0;
  for (int first : g.flows) {
    if (flows_[static_cast<std::size_t>(first)].marked == splits_) continue;
    to_visit_.assign(1, first);
    flows_[static_cast<std::size_t>(first)].marked = splits_;
    while (!to_visit_.empty()) {
      Flow& f = flows_[static_cast<std::size_t>(to_visit_.back())];
      to_visit_.pop_back();
      f.part = parts;
      for (int ch : f.route) {
        const Channel& c = channels_[static_cast<std::size_t>(ch)];
        for (int i = 0; i < c.count; ++i) {
          Flow& t = flows_[static_cast<std::size_t>(c.flow(i))];
          if (t.marked == splits_) continue;
          t.marked = splits_;
          to_visit_.push_back(c.flow(i));
        }
      }
    }
    ++parts;
  }
  return parts;
}

// Gives each component of the group a group of its own: part 0 keeps it. A level's flows share its
// channel, so each level goes whole to one part, in the order it had: filling that part alone would
// take its levels in that order.
void MaxMinSolver::split(int group) {
  groups_[static_cast<std::size_t>(group)].ends = 0;
  const int parts = mark_parts(groups_[static_cast<std::size_t>(group)]);
  if (parts == 1) return;
  parts_.assign(1, group);
  for (int p = 1; p < parts; ++p) {
    if (free_groups_.empty()) {
      groups_.emplace_back();  // may move the groups: none is held across
      parts_.push_back(static_cast<int>(groups_.size() - 1));
    } else {
      parts_.push_back(free_groups_.back());
      free_groups_.pop_back();
    }
  }
  Group& whole = groups_[static_cast<std::size_t>(group)];
  std::swap(whole.levels, next_levels_);
  std::swap(whole.members, next_members_);
  whole.levels.clear();
  whole.members.clear();
  for (const Level& l : next_levels_) {
    const int part = flows_[static_cast<std::size_t>(next_members_[static_cast<std::size_t>(l.first)])].part;
    Group& g = groups_[static_cast<std::size_t>(parts_[static_cast<std::size_t>(part)])];
    const auto index = static_cast<int>(g.levels.size());
    g.levels.push_back({l.channel, l.share, static_cast<int>(g.members.size()), l.count});
    for (int m = l.first; m < l.first + l.count; ++m) {
      const int s = next_members_[static_cast<std::size_t>(m)];
      g.members.push_back(s);
      flows_[static_cast<std::size_t>(s)].level = index;
    }
  }
  to_visit_.swap(whole.flows);  // the flows, to share out
  whole.flows.clear();
  for (int s : to_visit_) {
    Flow& f = flows_[static_cast<std::size_t>(s)];
    Group& g = groups_[static_cast<std::size_t>(parts_[static_cast<std::size_t>(f.part)])];
    f.group = parts_[static_cast<std::size_t>(f.part)];
    f.in_group = static_cast<int>(g.flows.size());
    g.flows.push_back(s);
  }
  to_visit_.clear();
}

}  // namespace gcsim::machine
