#include "apps/programs/ring_program.hpp"

namespace gcsim::programs {

void ring_exchange(parix::Processor& p, int iterations, std::int64_t bytes) {
  const int n = p.count(), me = p.id();
  if (n == 1) return;
  const int right = (me + 1) % n, left = (me + n - 1) % n;
  // Open the two links in increasing order of peer id, so no cycle of processors waits for each
  // other's connect (both ends of a link must call connect).
  parix::Link to_right, from_left;
  if (n == 2) {
    // Right and left neighbour are the same processor: the 0->1 direction uses tag 0, the 1->0
    // direction tag 1, and both processors open tag 0 first.
    if (me == 0) {
      to_right = p.connect(right, 0);
      from_left = p.connect(left, 1);
    } else {
      from_left = p.connect(left, 0);
      to_right = p.connect(right, 1);
    }
  } else if (right < left) {
    to_right = p.connect(right, 0);
    from_left = p.connect(left, 0);
  } else {
    from_left = p.connect(left, 0);
    to_right = p.connect(right, 0);
  }
  const parix::Bytes payload(static_cast<std::size_t>(bytes), std::byte{1});
  parix::Bytes received;  // reused: each receive swaps storage with the runtime, allocating nothing
  for (int i = 0; i < iterations; ++i) {
    parix::Request s = p.isend(to_right, payload);
    p.recv(from_left, received);
    p.wait(s);
  }
}

}  // namespace gcsim::programs
