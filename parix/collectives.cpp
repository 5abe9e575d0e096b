#include "parix/collectives.hpp"

#include <cstdint>
#include <cstring>

namespace gcsim::parix {
namespace {

void send_to(Processor& p, int peer, std::span<const std::byte> data, const CollectiveOptions& o) {
  if (o.connect_per_message) {
    Link l = p.connect(peer, o.tag);
    p.send(l, data);
  } else {
    p.send(p.persistent_link(peer, o.tag), data);
  }
}

// Into a vector the caller may reuse across a loop: its old storage goes back to the runtime.
void recv_from(Processor& p, int peer, const CollectiveOptions& o, Bytes& into) {
  if (o.connect_per_message) {
    Link l = p.connect(peer, o.tag);
    p.recv(l, into);
    return;
  }
  p.recv(p.persistent_link(peer, o.tag), into);
}

Bytes recv_from(Processor& p, int peer, const CollectiveOptions& o) {
  Bytes b;
  recv_from(p, peer, o, b);
  return b;
}

int rank_of(int id, int root, int n) { return (id - root + n) % n; }
int id_of(int rank, int root, int n) { return (rank + root) % n; }

// Packs contributions as [int32 id][int64 size][bytes]..., in the order given.
void append_packet(Bytes& out, int id, std::span<const std::byte> data) {
  const std::int32_t i = id;
  const std::int64_t n = static_cast<std::int64_t>(data.size());
  const auto* pi = reinterpret_cast<const std::byte*>(&i);
  const auto* pn = reinterpret_cast<const std::byte*>(&n);
  out.insert(out.end(), pi, pi + sizeof i);
  out.insert(out.end(), pn, pn + sizeof n);
  out.insert(out.end(), data.begin(), data.end());
}

// Each processor's part of a packed gather, as a view into the packet (empty where none came).
void unpack_views(std::span<const std::byte> in, std::vector<std::span<const std::byte>>& out) {
  std::size_t at = 0;
  while (at < in.size()) {
    std::int32_t i;
    std::int64_t n;
    if (in.size() - at < sizeof i + sizeof n) throw ParixError("gather: truncated packet");
    std::memcpy(&i, in.data() + at, sizeof i);
    std::memcpy(&n, in.data() + at + sizeof i, sizeof n);
    at += sizeof i + sizeof n;
    if (n < 0 || static_cast<std::size_t>(n) > in.size() - at || i < 0 || static_cast<std::size_t>(i) >= out.size()) {
      throw ParixError("gather: corrupt packet");
    }
    out[i] = in.subspan(at, std::size_t(n));
    at += n;
  }
}

void unpack(std::span<const std::byte> in, std::vector<Bytes>& out) {
  std::vector<std::span<const std::byte>> views(out.size());
  unpack_views(in, views);
  for (std::size_t i = 0; i < out.size(); ++i) out[i].assign(views[i].begin(), views[i].end());
}

}  // namespace

int tree_parent(int id, int root, int count) {
  const int r = rank_of(id, root, count);
  return r == 0 ? -1 : id_of((r - 1) / 2, root, count);
}

std::vector<int> tree_children(int id, int root, int count) {
  const int r = rank_of(id, root, count);
  std::vector<int> c;
  for (int k = 2 * r + 1; k <= 2 * r + 2 && k < count; ++k) c.push_back(id_of(k, root, count));
  return c;
}

Bytes broadcast(Processor& p, int root, Bytes data, const CollectiveOptions& o) {
  const int n = p.count(), me = p.id();
  if (n == 1) return data;
  if (o.algo == BcastAlgo::sequential) {
    if (me == root) {
      for (int q = 0; q < n; ++q) {
        if (q != root) send_to(p, q, data, o);
      }
      return data;
    }
    return recv_from(p, root, o);
  }
  if (me != root) data = recv_from(p, tree_parent(me, root, n), o);
  for (int c : tree_children(me, root, n)) send_to(p, c, data, o);
  return data;
}

namespace {

// Every contribution, packed as [id][size][bytes] records in arrival order, at the root; an empty
// packet elsewhere. The packet is what travels, so allgather can broadcast it as it is.
Bytes gather_packed(Processor& p, int root, std::span<const std::byte> mine, const CollectiveOptions& o) {
  const int n = p.count(), me = p.id();
  Bytes packet;
  if (o.algo == BcastAlgo::sequential) {
    if (me != root) {
      send_to(p, root, mine, o);
      return packet;
    }
    append_packet(packet, me, mine);
    Bytes in;
    for (int q = 0; q < n; ++q) {
      if (q == root) continue;
      recv_from(p, q, o, in);
      append_packet(packet, q, in);
    }
    return packet;
  }
  // Tree: each processor forwards its own contribution and its subtree's, packed, to its parent.
  append_packet(packet, me, mine);
  Bytes sub;
  for (int c : tree_children(me, root, n)) {
    recv_from(p, c, o, sub);
    packet.insert(packet.end(), sub.begin(), sub.end());
  }
  if (me != root) {
    send_to(p, tree_parent(me, root, n), packet, o);
    packet.clear();
  }
  return packet;
}

}  // namespace

std::vector<Bytes> gather(Processor& p, int root, std::span<const std::byte> mine, const CollectiveOptions& o) {
  const Bytes packet = gather_packed(p, root, mine, o);
  std::vector<Bytes> all;
  if (p.id() == root) {
    all.resize(p.count());
    unpack(packet, all);
  }
  return all;
}

std::vector<Bytes> allgather(Processor& p, std::span<const std::byte> mine, const CollectiveOptions& o) {
  const Bytes packed = broadcast(p, 0, gather_packed(p, 0, mine, o), o);
  std::vector<Bytes> all(p.count());
  unpack(packed, all);
  return all;
}

std::size_t GatheredBytes::size() const {
  std::size_t bytes = 0;
  for (const auto& part : parts) bytes += part.size();
  return bytes;
}

bool GatheredBytes::same_as(std::span<const std::byte> whole) const {
  std::size_t at = 0;
  for (const auto& part : parts) {
    if (part.size() > whole.size() - at || (!part.empty() && std::memcmp(whole.data() + at, part.data(), part.size()) != 0))
      return false;
    at += part.size();
  }
  return at == whole.size();
}

GatheredBytes allgather_views(Processor& p, std::span<const std::byte> mine, const CollectiveOptions& o) {
  GatheredBytes g;
  g.packed = broadcast(p, 0, gather_packed(p, 0, mine, o), o);
  g.parts.resize(std::size_t(p.count()));
  unpack_views(g.packed, g.parts);
  return g;
}

Bytes reduce(Processor& p, int root, Bytes mine, const CombineOp& op, const CollectiveOptions& o) {
  const int n = p.count(), me = p.id();
  if (o.algo == BcastAlgo::sequential) {
    if (me != root) {
      send_to(p, root, mine, o);
      return {};
    }
    Bytes in;
    for (int q = 0; q < n; ++q) {
      if (q == root) continue;
      recv_from(p, q, o, in);
      op(mine, in);
    }
    return mine;
  }
  Bytes in;
  for (int c : tree_children(me, root, n)) {
    recv_from(p, c, o, in);
    op(mine, in);
  }
  if (me != root) {
    send_to(p, tree_parent(me, root, n), mine, o);
    return {};
  }
  return mine;
}

Bytes allreduce(Processor& p, Bytes mine, const CombineOp& op, const CollectiveOptions& o) {
  return broadcast(p, 0, reduce(p, 0, std::move(mine), op, o), o);
}

void barrier(Processor& p, const CollectiveOptions& o) {
  allreduce(p, Bytes{}, [](Bytes&, std::span<const std::byte>) {}, o);
}

}  // namespace gcsim::parix
