#pragma once
// The simulated runtime's state: the Simulation owns the kernel, the network and the machine, and
// composes the runtime's parts -- message transport, the node-memory ledger, connection matching
// and the processes' lifetime -- that the processes (SimProcess) use. Internal to parix/sim/:
// applications use parix/sim/simulated_runtime.hpp.
#include <algorithm>
#include <chrono>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include "machine/connection_service.hpp"
#include "machine/kernel.hpp"
#include "machine/interconnect.hpp"
#include "machine/interconnect_registry.hpp"
#include "machine/network_model.hpp"
#include "machine/node.hpp"
#include "machine/trace.hpp"
#include "parix/placement.hpp"
#include "parix/sim/connection_matching.hpp"
#include "parix/sim/link_end.hpp"
#include "parix/sim/link_table.hpp"
#include "parix/sim/memory_ledger.hpp"
#include "parix/sim/message_transport.hpp"
#include "parix/sim/payload_pool.hpp"
#include "parix/sim/post_office.hpp"
#include "parix/sim/process_lifetime.hpp"
#include "parix/sim/request_pool.hpp"
#include "parix/sim/sim_process.hpp"
#include "parix/sim/simulated_runtime.hpp"

namespace gcsim::parix::detail {

using machine::Kernel;
using machine::TraceKind;
using machine::TraceRecord;

class Simulation {
 public:
  explicit Simulation(const SimulationOptions& o)
      : config(o.config),
        interconnect(machine::make_interconnect(config)),
        trace(o.trace, processor_count(o), *interconnect),
        network(machine::make_network_model(config.network_model,
                                            {kernel, *interconnect, config, trace.enabled() ? &trace : nullptr})),
        connections(config, *interconnect),
        nodes(make_nodes(kernel, config, o.memory_limit)),
        stats(static_cast<std::size_t>(processor_count(o))),
        node_of(checked_placement(o.placement, config.nodes)),
        processors(static_cast<int>(node_of.size())),
        memory(nodes, node_of),
        processes(kernel, stats, static_cast<std::size_t>(config.fiber_stack_bytes)),
        transport({kernel, *network, trace, memory, payloads, links, processes}),
        post_office({kernel, *network, connections, stats, node_of, trace, requests, payloads}) {}

  RunResult run(const std::function<void(Processor&)>& program);
  // The run's figures; an interrupted run's makespan is the kernel's clock when it stopped.
  RunResult result(std::chrono::steady_clock::time_point wall_start, bool interrupted) const;

  RequestPool requests;      // first member: outlives every request the others hold
  PayloadPool payloads;      // messages' storage, recycled (parix/sim/payload_pool.hpp)
  machine::MachineConfig config;
  // Whether [comm_cpu] charges anything: asked on every send and receive.
  const bool charges_comm_cpu = config.comm_cpu.any();
  machine::Kernel kernel;
  std::unique_ptr<const machine::Interconnect> interconnect;  // [topology] interconnect (the GC's mesh)
  machine::TraceWriter trace;
  std::unique_ptr<machine::NetworkModel> network;
  machine::ConnectionService connections;
  std::deque<machine::Node> nodes;
  std::vector<ProcessorStats> stats;
  std::vector<int> node_of;  // processor -> node (SimulationOptions::placement)
  int processors;            // node_of.size(): config.nodes unless the placement packs several on a node
  MemoryLedger memory;
  LinkTable<LinkEnd> links;
  ProcessLifetime processes;
  MessageTransport transport;
  ConnectionMatching connect_matching;
  PostOffice post_office;  // addressed messages (parix/mailbox.hpp)

 private:
  static int processor_count(const SimulationOptions& o) {
    return std::max(o.config.nodes, static_cast<int>(o.placement.size()));
  }
  static std::deque<machine::Node> make_nodes(machine::Kernel& kernel, const machine::MachineConfig& config,
                                              machine::MemoryLimit limit);
};

}  // namespace gcsim::parix::detail
