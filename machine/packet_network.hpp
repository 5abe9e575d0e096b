#pragma once
// Packet-level network: a message is cut into packets of at most `packet_bytes` (the machine
// file's [network] packet_bytes) that cross the mesh one channel after another by virtual
// cut-through: a packet's head moves on one hop latency after it entered a channel, and a channel
// carries one packet at a time for that packet's serialization time. Packets wait for busy
// channels, so contention, hot links near a broadcast root and a message stuck behind another's
// packets come out of the model rather than out of a fitted constant.
//
// Each channel keeps a calendar of the intervals its packets occupy. A message's packets are
// scheduled through every channel of the route when the message enters the network (one event per
// message, not per packet and hop); a packet takes the earliest free gap at or after the time it
// can be there, so a message scheduled later never delays one scheduled earlier, but may use the
// idle time between its packets. Packets of one message keep their order on every channel.
//
// A lone message on an idle network arrives at exactly the analytic model's time: set-up and
// network latency before the first channel, one hop latency per further hop, and the packets'
// serialization times adding up to the whole message's (packet boundaries are rounded on the
// cumulative byte count, as NetworkModel::serialization rounds the total).
#include <cstdint>
#include <vector>

#include "machine/calendar.hpp"
#include "machine/network_model.hpp"

namespace gcsim::machine {

class PacketNetwork final : public NetworkModel {
 public:
  explicit PacketNetwork(NetworkContext ctx);
  std::string_view name() const override { return "packet"; }
  void transfer(int src, int dst, std::int64_t bytes, Kernel::Action&& on_arrival) override;

  std::int64_t packet_bytes() const { return packet_bytes_; }
  // Packets scheduled so far (for tests and counters).
  std::uint64_t packets() const { return packets_; }

 private:
  std::int64_t packet_bytes_;
  std::vector<Calendar> calendar_;  // per channel: the intervals its packets occupy
  std::vector<int> route_;
  std::vector<SimTime> ready_;  // per hop: when the previous packet of this message left it
  std::uint64_t packets_ = 0;
};

}  // namespace gcsim::machine
