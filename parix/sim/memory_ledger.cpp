#include "parix/sim/memory_ledger.hpp"

namespace gcsim::parix::detail {

MemoryLedger::MemoryLedger(std::deque<machine::Node>& nodes, const std::vector<int>& node_of) {
  for (machine::Node& node : nodes) {
    in_flight_kind_ = node.memory().kind(kMessagesInFlight);
    received_kind_ = node.memory().kind(kMessagesReceived);
  }
  for (const int node : node_of) memory_of_.push_back(&nodes[node].memory());
}

std::string MemoryLedger::use(int processor, std::int64_t bytes, std::string_view kind) {
  return use(processor, bytes, memory_of_[processor]->kind(kind));
}

std::string MemoryLedger::use(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
  return declare(processor, bytes, kind) ? std::string() : refusal(processor, bytes, kind);
}

bool MemoryLedger::declare_beyond(int processor, std::int64_t bytes, machine::NodeMemory::Kind kind) {
  machine::NodeMemory& memory = *memory_of_[processor];
  if (!memory.add(bytes, kind)) return false;
  if (memory.over() && warning_.empty()) warning_ = memory.report(processor, 0, memory.kind_name(kind));
  return true;
}

}  // namespace gcsim::parix::detail
