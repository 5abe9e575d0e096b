#pragma once
// What a collective algorithm needs of the runtime: point-to-point messages among the ranks of one
// communicator, on a context of their own (so that no user receive, wildcards included, can match
// them), and the node's CPU for combining reduction operands. The layer's runtime implements it once
// per communicator over the simulated machine; tests implement it in memory. Algorithms
// (collective_algorithms.hpp) see only this, so each is a schedule of messages that the machine
// model then costs: contention on the mesh and connection set-up show as they would on the GC.
#include <cstddef>
#include <span>

namespace gcsim::mpi_layer {

class CollectiveChannel {
 public:
  using Handle = int;  // one started send or receive, until wait_all finishes it

  virtual ~CollectiveChannel() = default;
  virtual int rank() const = 0;  // this rank in the communicator
  virtual int size() const = 0;  // ranks in the communicator

  // Starts sending data to peer (a rank of the communicator) under tag; data must stay unchanged
  // until the handle is waited for. Messages between a pair under one tag arrive in order.
  virtual Handle start_send(int peer, int tag, std::span<const std::byte> data) = 0;
  // Starts receiving the message from peer under tag into `into`, which must be exactly its size
  // (a collective always knows what it receives; another size is an internal error, thrown).
  virtual Handle start_recv(int peer, int tag, std::span<std::byte> into) = 0;
  // Blocks until every handle is finished; the handles are then spent.
  virtual void wait_all(std::span<const Handle> handles) = 0;
  // Charges the node's CPU for applying a reduction operation to `bytes` bytes of operands.
  virtual void charge_reduction(std::size_t bytes) = 0;
};

}  // namespace gcsim::mpi_layer
