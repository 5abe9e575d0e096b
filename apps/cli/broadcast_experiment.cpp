#include "apps/cli/broadcast_experiment.hpp"

#include <vector>

namespace gcsim::cli {
namespace {

constexpr int kTag = 4402;  // section 4.4.2

void send_one(parix::Processor& p, int peer, const parix::Bytes& payload, bool connect_only) {
  parix::Link l = p.connect(peer, kTag);
  if (!connect_only) p.send(l, payload);
}

void recv_one(parix::Processor& p, int peer, bool connect_only) {
  parix::Link l = p.connect(peer, kTag);
  if (!connect_only) p.recv(l);
}

}  // namespace

void all_node_broadcast(parix::Processor& p, std::int64_t bytes, parix::BcastAlgo algo) {
  const int n = p.count(), me = p.id(), root = 0;
  const bool connect_only = bytes == 0;
  const parix::Bytes payload(static_cast<std::size_t>(bytes), std::byte{0x5a});
  if (n == 1) return;
  if (algo == parix::BcastAlgo::sequential) {
    // Every node sends to the root in turn; then the root sends to every node in turn.
    if (me == root) {
      for (int q = 1; q < n; ++q) recv_one(p, q, connect_only);
      for (int q = 1; q < n; ++q) send_one(p, q, payload, connect_only);
    } else {
      send_one(p, root, payload, connect_only);
      recv_one(p, root, connect_only);
    }
    return;
  }
  // Tree: from the leaves up to the root, then from the root back down to the leaves.
  const int parent = parix::tree_parent(me, root, n);
  const std::vector<int> children = parix::tree_children(me, root, n);
  for (int c : children) recv_one(p, c, connect_only);
  if (parent >= 0) {
    send_one(p, parent, payload, connect_only);
    recv_one(p, parent, connect_only);
  }
  for (int c : children) send_one(p, c, payload, connect_only);
}

}  // namespace gcsim::cli
