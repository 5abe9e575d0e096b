#pragma once
// When a virtual link is up. PARIX opens a virtual link (a connection) in software on the
// communication processors; the thesis measures that it dominates its broadcasts (tables 4.6,
// 4.7) but does not say how set-ups proceed side by side. The machine file chooses
// ([network] connect_model):
//   parallel    every set-up proceeds at once, whatever else is being set up;
//   serialized  one connection server for the whole machine: set-ups queue for it in request order;
//   servers     one connection server per block of WxH nodes ([network] connect_server_block): a
//               set-up holds the servers of both ends' blocks, so set-ups within a block queue,
//               and set-ups in different blocks proceed side by side. Blocks are cut from the
//               interconnect's coordinates (Interconnect::coordinates); a block as large as the
//               grid is `serialized`; a 1x1 block means each node handles one set-up at a time.
//   route       a set-up holds every link of its route (both directions, Interconnect::link_of)
//               while it proceeds, so set-ups whose routes share a link queue, and disjoint ones
//               proceed together.
// A set-up takes connect_base + connect_per_hop * hops in every model; only the waiting differs.
#include <vector>

#include "machine/calendar.hpp"
#include "machine/machine_config.hpp"
#include "machine/interconnect.hpp"

namespace gcsim::machine {

class ConnectionService {
 public:
  ConnectionService(const MachineConfig& config, const Interconnect& interconnect);

  // Both ends of a link between nodes a and b have asked for it by `requested`; reserves what
  // the set-up holds and returns when the link is up.
  SimTime set_up(int a, int b, SimTime requested);
  // How long the set-up itself takes, without waiting.
  SimTime duration(int a, int b) const;

 private:
  int server_of(int node) const;
  // The calendars a set-up between a and b holds.
  void held_by(int a, int b, std::vector<Calendar*>& out);
  const MachineConfig& config_;
  const Interconnect& net_;
  std::vector<Calendar> servers_;  // per server, or per undirected link (Interconnect::link_of)
  std::vector<int> route_;
  std::vector<Calendar*> held_;
};

}  // namespace gcsim::machine
