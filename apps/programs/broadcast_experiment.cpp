#include "apps/programs/broadcast_experiment.hpp"

#include <cctype>
#include <cerrno>
#include <cstdlib>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "apps/pipeline/resource_check.hpp"

namespace gcsim::programs {
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

std::int64_t parse_message_size(const std::string& text) {
  auto fail = [&](std::string_view why) {
    return std::invalid_argument(fmt::format("--size {}: {} (e.g. 0, 512, 16KB, 4MB; 1KB = 1024 bytes)", text, why));
  };
  std::size_t i = 0;
  while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
  if (i < text.size() && text[i] == '-') throw fail("a message size must be positive (or 0: connect only)");
  const std::size_t digits = i;
  while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
  if (i == digits) throw fail("expected a whole number of bytes");
  errno = 0;
  const unsigned long long number = std::strtoull(text.c_str() + digits, nullptr, 10);
  std::string unit;
  for (; i < text.size(); ++i)
    if (!std::isspace(static_cast<unsigned char>(text[i]))) unit += char(std::toupper(static_cast<unsigned char>(text[i])));
  int shift = -1;
  if (unit.empty() || unit == "B") shift = 0;
  else if (unit == "K" || unit == "KB" || unit == "KIB") shift = 10;
  else if (unit == "M" || unit == "MB" || unit == "MIB") shift = 20;
  else if (unit == "G" || unit == "GB" || unit == "GIB") shift = 30;
  else if (unit == "T" || unit == "TB" || unit == "TIB") shift = 40;
  if (shift < 0) throw fail(fmt::format("unknown unit '{}' (B, KB, MB, GB or TB)", unit));
  constexpr unsigned long long kMax = std::numeric_limits<std::int64_t>::max();
  if (errno == ERANGE || number > (kMax >> shift)) throw fail("too large");
  return static_cast<std::int64_t>(number << shift);
}

void check_broadcast_resources(std::int64_t bytes, int nodes, std::int64_t node_bytes, machine::MemoryLimit limit) {
  // Each node holds its data and, while it sends, the runtime's copy of the message.
  pipeline::check_node_memory({{"broadcast data", bytes}, {"messages in flight", bytes}}, 0, node_bytes, limit);
  pipeline::check_host_memory(pipeline::saturating_product(2 * std::int64_t(nodes), bytes),
                              fmt::format("a broadcast of {} per message on {} nodes", machine::format_bytes(bytes), nodes));
}

void all_node_broadcast(parix::Processor& p, std::int64_t bytes, parix::BcastAlgo algo) {
  const int n = p.count(), me = p.id(), root = 0;
  const bool connect_only = bytes == 0;
  // Every node's data, declared on its node before the host allocates it.
  const parix::MemoryReservation held = p.reserve_memory(bytes, "broadcast data");
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

}  // namespace gcsim::programs
