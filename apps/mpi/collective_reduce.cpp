// Reduce on a binomial tree: relative rank rel receives the partial results of the subtrees
// rel + 1, rel + 2, rel + 4, ... (each covering the next ranks in order) and sends its own to
// rel - lowest bit. Each partial covers consecutive ranks, and a node combines its lower-rank
// partial as `in`, so a non-commutative op keeps the standard's order when the tree is rooted at
// rank 0: such an op is reduced at rank 0 and the result sent on to the root (one more message),
// as MPICH does.
#include "apps/mpi/collective_steps.hpp"

namespace gcsim::mpi_layer {
namespace {

// Leaves the subtree's result in acc at relative rank 0 (tree_root) and returns there.
void binomial_tree(const CollectiveCall& call, steps::Bytes& acc, std::size_t count, const Reduction& reduction,
                   int tree_root) {
  const int n = call.channel.size(), rel = steps::relative_rank(call.channel.rank(), tree_root, n);
  steps::Bytes partial(acc.size());
  for (int mask = 1; mask < n; mask *= 2) {
    if ((rel & mask) != 0) {
      steps::send(call, CollectivePhase::ReduceTree, steps::absolute_rank(rel - mask, tree_root, n), acc);
      return;
    }
    if (rel + mask >= n) continue;
    steps::recv(call, CollectivePhase::ReduceTree, steps::absolute_rank(rel + mask, tree_root, n), partial);
    steps::combine(call, reduction, acc.data(), partial.data(), count);  // mine (lower ranks) op theirs
    acc.swap(partial);
  }
}

}  // namespace

void reduce(const CollectiveCall& call, std::span<const std::byte> send, std::span<std::byte> result,
            std::size_t count, const Reduction& reduction, int root, Algorithm algorithm) {
  const int r = call.channel.rank();
  resolve_algorithm(Collective::Reduce, algorithm, {.ranks = call.channel.size()});  // only checks the name
  if (count == 0) return;
  steps::Bytes acc(send.begin(), send.end());
  const int tree_root = reduction.commutative ? root : 0;
  binomial_tree(call, acc, count, reduction, tree_root);
  if (tree_root != root) {
    if (r == tree_root) steps::send(call, CollectivePhase::ReduceForward, root, acc);
    if (r == root) steps::recv(call, CollectivePhase::ReduceForward, tree_root, result);
    return;
  }
  if (r == root) steps::copy(acc, result);
}

}  // namespace gcsim::mpi_layer
