// The C entry points that make, compare and free communicators (MPI 3.1 sections 6.4.1-6.4.3).
// Every child gets a context of its own (communicator.hpp), so messages never cross communicators.
#include <algorithm>
#include <cstring>
#include <vector>

#include "apps/mpi/c_call.hpp"
#include "apps/mpi/group.hpp"
#include "apps/mpi/runtime/attributes.hpp"
#include "apps/mpi/runtime/rank_channel.hpp"

using namespace gcsim::mpi_layer;

namespace {

enum Tag { kSplit = 4 };

// Every member's (color, key), in communicator-rank order: a fan-in to rank 0 and a fan-out.
std::vector<std::array<int, 2>> all_color_keys(RankChannel& ch, int color, int key) {
  std::vector<std::array<int, 2>> table(static_cast<std::size_t>(ch.size()));
  const std::array<int, 2> mine{color, key};
  auto bytes = [](auto& v) { return std::as_writable_bytes(std::span(v)); };
  std::vector<CollectiveChannel::Handle> hs;
  if (ch.rank() == 0) {
    table[0] = mine;
    for (int r = 1; r < ch.size(); ++r) hs.push_back(ch.start_recv(r, kSplit, bytes(table).subspan(r * 8, 8)));
    ch.wait_all(hs);
    hs.clear();
    for (int r = 1; r < ch.size(); ++r) hs.push_back(ch.start_send(r, kSplit, bytes(table)));
  } else {
    hs.push_back(ch.start_send(0, kSplit, std::as_bytes(std::span(mine))));
    hs.push_back(ch.start_recv(0, kSplit, bytes(table)));
  }
  ch.wait_all(hs);
  return table;
}

MPI_Comm child(Rank& rank, Communicator& parent, std::vector<int> members) {
  const std::int64_t context = parent.next_child_context();  // every member advances, even a non-member
  const int world = rank.world_rank();
  const auto me = std::find(members.begin(), members.end(), world);
  if (me == members.end()) return MPI_COMM_NULL;
  Communicator c;
  c.rank = static_cast<int>(me - members.begin());
  c.members = std::make_shared<const std::vector<int>>(std::move(members));
  c.context = context;
  c.errhandler = parent.errhandler;  // section 8.3.1: a new communicator inherits its parent's
  return rank.add_comm(std::move(c));
}

}  // namespace

extern "C" {

int MPI_Comm_dup(MPI_Comm comm, MPI_Comm* newcomm) {
  return runtime_call([&](Rank& rank) {
    Communicator& parent = rank.comm(comm);
    MPI_Comm& out = out_arg(newcomm);
    const MPI_Comm dup = child(rank, parent, *parent.members);
    rank.comm(dup).cart = parent.cart;  // a duplicate keeps the topology, as the standard says
    rank.comm(dup).graph = parent.graph;
    try {
      copy_attributes(rank, comm, dup);  // a callback's error fails the dup, its copies deleted
    } catch (const Error&) {
      delete_attributes(rank, dup);
      rank.free_comm(dup);
      throw;
    }
    out = dup;
  });
}

int MPI_Comm_split(MPI_Comm comm, int color, int key, MPI_Comm* newcomm) {
  return runtime_call([&](Rank& rank) {
    MPI_Comm& out = out_arg(newcomm);
    if (color < 0 && color != MPI_UNDEFINED) fail(MPI_ERR_ARG, "negative color");
    RankChannel ch(rank, comm, "MPI_Comm_split(comm=" + Rank::comm_name(comm) + ")");
    Communicator& parent = rank.comm(comm);
    const auto table = all_color_keys(ch, color, key);
    std::vector<int> ranks;  // of the parent, same color, ordered by (key, parent rank)
    for (int r = 0; r < parent.size(); ++r) {
      if (color != MPI_UNDEFINED && table[static_cast<std::size_t>(r)][0] == color) ranks.push_back(r);
    }
    std::stable_sort(ranks.begin(), ranks.end(), [&](int a, int b) { return table[static_cast<std::size_t>(a)][1] < table[static_cast<std::size_t>(b)][1]; });
    std::vector<int> members;
    for (int r : ranks) members.push_back(parent.world_rank_of(r));
    out = child(rank, parent, std::move(members));
  });
}

int MPI_Comm_create(MPI_Comm comm, MPI_Group group, MPI_Comm* newcomm) {
  return runtime_call([&](Rank& rank) {
    Communicator& parent = rank.comm(comm);
    const Group& g = group_arg(rank.registry(), group);
    std::vector<int> members(g.members().begin(), g.members().end());
    for (int w : members) {
      if (parent.rank_of_world(w) < 0) fail(MPI_ERR_GROUP, "the group is not a subset of the communicator's");
    }
    out_arg(newcomm) = child(rank, parent, std::move(members));
  });
}

int MPI_Comm_free(MPI_Comm* comm) {
  return runtime_call([&](Rank& rank) {
    MPI_Comm& c = out_arg(comm);
    rank.comm(c);
    if (c == MPI_COMM_WORLD || c == MPI_COMM_SELF) fail(MPI_ERR_COMM, "cannot free a predefined communicator");
    delete_attributes(rank, c);  // the delete callbacks first, as the standard says
    rank.free_comm(c);
    c = MPI_COMM_NULL;
  });
}

int MPI_Comm_compare(MPI_Comm comm1, MPI_Comm comm2, int* result) {
  return runtime_call([&](Rank& rank) {
    const Communicator& a = rank.comm(comm1);
    const Communicator& b = rank.comm(comm2);
    int& out = out_arg(result);
    if (comm1 == comm2) out = MPI_IDENT;
    else if (*a.members == *b.members) out = MPI_CONGRUENT;
    else out = compare_groups(Group(*a.members), Group(*b.members)) == MPI_SIMILAR ? MPI_SIMILAR : MPI_UNEQUAL;
  });
}

int MPI_Comm_group(MPI_Comm comm, MPI_Group* group) {
  return runtime_call([&](Rank& rank) {
    const Communicator& c = rank.comm(comm);
    out_arg(group) = rank.registry().groups.insert(Group(*c.members));
  });
}

}  // extern "C"
