#pragma once
// The node-memory ledger of a simulated run: what each processor declares on its node (the
// application's kinds and the runtime's copies of messages), checked against the node's memory.
// A run that only warns keeps the first overrun's report.
#include <cstdint>
#include <deque>
#include <string>
#include <string_view>
#include <vector>

#include "machine/node.hpp"
#include "machine/node_memory.hpp"

namespace gcsim::parix::detail {

class MemoryLedger {
 public:
  // Node memory the runtime itself holds for messages, declared on every message. Registered first
  // on every node, so each kind has the same handle on all of them.
  static constexpr std::string_view kMessagesInFlight = "messages in flight";
  static constexpr std::string_view kMessagesReceived = "messages received";

  // node_of: processor -> node. The nodes must outlive the ledger and never move (a deque's don't).
  MemoryLedger(std::deque<machine::Node>& nodes, const std::vector<int>& node_of);

  machine::NodeMemory::Kind in_flight_kind() const { return in_flight_kind_; }
  machine::NodeMemory::Kind received_kind() const { return received_kind_; }
  const machine::NodeMemory& of(int processor) const { return *memory_of_[processor]; }
  // The first overrun of a run that only warns; empty if none.
  const std::string& warning() const { return warning_; }

  // Declares memory on the node of `processor` (negative: releases). Returns "" when granted,
  // else the out-of-memory report to raise.
  std::string use(int processor, std::int64_t bytes, std::string_view kind);
  std::string use(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind);
  // The same by handle without building a report, the form the runtime uses on every message:
  // true when granted; when refused, refusal() is the report. Inline: it runs twice per message.
  bool declare(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
    machine::NodeMemory& memory = *memory_of_[processor];
    if (!memory.use(bytes, kind)) return false;
    if (memory.over() && warning_.empty()) warning_ = memory.report(processor, 0, memory.kind_name(kind));
    return true;
  }
  // The same for bytes > 0, a message's: within the node's memory in line (NodeMemory::add_within),
  // an overrun (refused, or granted with a warning) out of line.
  bool declare_message(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
    if (memory_of_[processor]->add_within(bytes, kind)) [[likely]] return true;
    return declare_beyond(processor, bytes, kind);
  }
  // Gives back bytes > 0 declared before. Never fails, and needs no warning: a node over its
  // memory got there by a declaration, which kept the first warning.
  void release(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
    memory_of_[processor]->release(bytes, kind);
  }
  // The bytes of a message from `sender` that arrived, declared in flight on its node when it was
  // sent (which threw when refused, so every message in flight holds its bytes there).
  void release_in_flight(int sender, std::int64_t bytes) { memory_of_[sender]->give_back(bytes, in_flight_kind_); }
  std::string refusal(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) const {
    const machine::NodeMemory& memory = *memory_of_[processor];
    return memory.report(processor, bytes, memory.kind_name(kind));
  }

 private:
  [[gnu::noinline]] bool declare_beyond(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind);

  // processor -> its node's memory: what every message declares to, without the deque's lookup.
  std::vector<machine::NodeMemory*> memory_of_;
  machine::NodeMemory::Kind in_flight_kind_ = 0;
  machine::NodeMemory::Kind received_kind_ = 0;
  std::string warning_;
};

}  // namespace gcsim::parix::detail
