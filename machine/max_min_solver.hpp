#pragma once
// Max-min fair rates of flows over shared channels of equal capacity, by progressive filling:
// repeatedly saturate the channel that offers the smallest equal share left / unassigned to the
// flows still without a rate (the lowest-numbered one on a tie) and fix those flows at that share.
// The rates depend only on the set of flows (each channel's capacity is given out in increasing
// share order whatever the order of insertion), so a solve over all flows gives every flow the
// same rate, bit for bit, as a solve over its connected component.
//
// Each start or end changes a few rates out of hundreds, so the solver keeps the levels of the last
// solution of each group of linked flows (channel, share, flows fixed) and replays the changed
// flow's group: a channel whose state (capacity left, flows without a rate) is the same as at the
// same point of the last solution needs no look, since it offered no less than the level the last
// solution took there. Only the channels whose state differs (the perturbed ones: on the changed
// flow's route, then on the routes of flows fixed differently) are scanned. Levels whose channel is
// unperturbed are replayed as they were; the others are dropped and their flows refilled. The
// result is what a full solve gives, bit for bit (tests/machine/max_min_solver_test.cpp compares).
#include <array>
#include <climits>
#include <cstdint>
#include <vector>

namespace gcsim::machine {

class MaxMinSolver {
 public:
  MaxMinSolver(int channels, double capacity);

  // A free flow slot; fill route(slot) with its channels, then start it.
  int open();
  std::vector<int>& route(int slot) { return flows_[static_cast<std::size_t>(slot)].route; }
  // Adds the flow to its channels and re-solves; changed() then holds its slot too.
  void start(int slot);
  // Removes the flow and re-solves; the slot may be reused by the next open().
  void finish(int slot);

  double rate(int slot) const { return flows_[static_cast<std::size_t>(slot)].rate; }
  // The flows whose rate the last start or finish changed (the started one included), unordered.
  const std::vector<int>& changed() const { return changed_; }
  std::size_t active() const { return active_; }
  // Groups with flows (for tests).
  std::size_t groups() const { return groups_.size() - free_groups_.size(); }

 private:
  static constexpr int kNoLevel = INT_MAX;  // at the capacity of its own channels, or new
  struct Flow {
    std::vector<int> route;
    int level = kNoLevel;    // index in levels_ of the last solution
    double rate = 0;
    bool fresh = false;      // started since the last solution: its rate counts as changed
    std::uint64_t fixed = 0;  // the solve that gave it new_rate
    double new_rate = 0;
    std::uint64_t crossed = 0;  // the solve whose perturbed channels `first_crossed` lists
    int first_crossed = -1;     // in crossings_: the perturbed channels it crosses
    int group = -1;             // in groups_
    int in_group = -1;          // its place in the group's flows
    std::uint64_t marked = 0;   // the split that gave it `part`
    int part = 0;
  };
  struct Level {
    int channel;
    double share;
    int first, count;  // its flows in members_
  };
  // A channel's started flows and, while perturbed (perturbed == the solve under way), its state,
  // in one cache line: the first look at a channel in a solve (a few hundred per solve, spread over
  // the mesh) misses once. Most channels carry at most four flows; the others keep the rest apart.
  // The order of a channel's flows is moot (see finish).
  struct alignas(64) Channel {
    std::uint64_t perturbed = 0;
    double left = 0;     // capacity not yet given out
    int unassigned = 0;  // flows without a rate
    int count = 0;       // started flows on it
    static constexpr int kNear = 4;
    std::array<int, kNear> near{};
    std::vector<int> far;
    int flow(int i) const { return i < kNear ? near[static_cast<std::size_t>(i)] : far[static_cast<std::size_t>(i - kNear)]; }
    void add(int slot);
    void remove(int slot);
  };
  struct Crossing {
    int channel, next;
  };
  // Flows linked through shared channels, directly or not, and the levels of their last solution
  // (its flows level after level in `members`). A solve replays its own group's levels only. A start
  // joins the groups its route touches. An end may leave a group in several components, which a
  // solve over the group handles alike (each gets the same rates): the group is split only now and
  // then, once it has seen as many ends as it has flows.
  struct Group {
    std::vector<Level> levels;
    std::vector<int> members;
    std::vector<int> flows;  // all its started flows
    std::uint64_t seen = 0;  // scratch of join()
    std::size_t ends = 0;    // since it was last split
  };

  // Groups (machine/max_min_groups.cpp).
  int join(int slot);
  void merge(int into, int from);
  void leave(int slot);
  void split(int group);
  int mark_parts(const Group& g);

  void solve(int group, const std::vector<int>& seed, int started, int finished);
  // Most calls find the channel perturbed already: that check is inline, the work is not.
  void perturb(int ch, std::size_t k) {
    if (channels_[static_cast<std::size_t>(ch)].perturbed != solve_) perturb_now(ch, k);
  }
  void perturb_now(int ch, std::size_t k);
  void take(int ch, double share);
  void consider(int ch);
  void offer(int ch, const Channel& c);
  void replay(std::size_t k);
  void skip(std::size_t k);
  void fix(int ch, double share, std::size_t k);
  bool tightest_perturbed(int& best, double& best_share);
  void settle();

  double capacity_;
  std::vector<Flow> flows_;
  std::vector<int> free_slots_;
  std::size_t active_ = 0;
  std::vector<Channel> channels_;

  std::vector<Group> groups_;
  std::vector<int> free_groups_;
  std::uint64_t joins_ = 0;
  std::vector<int> joined_;  // join's groups met
  std::uint64_t splits_ = 0;
  std::vector<int> parts_;    // split's scratch: the group of each part, and flows to visit
  std::vector<int> to_visit_;

  // The group being solved; the solve writes its new levels next to its last ones, then swaps.
  Group* group_ = nullptr;
  std::vector<Level> next_levels_;
  std::vector<int> next_members_;

  // Scratch of a solve, kept so that a solve allocates nothing.
  std::uint64_t solve_ = 0;
  std::vector<int> live_;       // perturbed shared channels that had flows to fix when last scanned
  // The live channel offering the smallest share, kept up to date as channels change and
  // rescanned only when it changes itself (replays seldom touch it).
  int best_ = -1;
  double best_share_ = 0;
  bool best_stale_ = false;
  std::vector<Crossing> crossings_;  // per flow without a rate, lists of perturbed channels
  std::vector<int> touched_;         // flows given a rate other than by replay
  std::vector<int> unsettled_;       // flows that may end at the capacity: dropped levels', the new
  int finished_ = -1;                // the flow leaving, which is in a dropped level but gets no rate
  std::vector<int> changed_;
  std::vector<int> earlier_;         // perturb's levels of a channel's fixed flows
};

}  // namespace gcsim::machine
