// Every reduction collective, with every algorithm, on 1..16 ranks, every root, zero and non-zero
// counts and every op case (a non-commutative one included), against the sequential reference.
#include "tests/mpi_layer/collective_test_support.hpp"

namespace gcsim::mpi_layer::testing {
namespace {

constexpr std::size_t counts[] = {0, 1, 5, 37};

TEST(MpiCollectiveResults, ReduceEqualsTheRankOrderFoldAtEveryRoot) {
  for (const OpCase& op : op_cases())
    for (int n : rank_counts)
      for (std::size_t count : {std::size_t{0}, std::size_t{5}}) {
        const std::vector<Bytes> in = inputs_of(op, n, count);
        const Bytes expected = reference_fold(op, in, 0, n, count);
        for (int root = 0; root < n; ++root) {
          const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
            Bytes result(r == root ? count * op.reduction.element_size : 0);
            reduce(call, in[static_cast<std::size_t>(r)], result, count, op.reduction, root);
            return result;
          });
          EXPECT_EQ(out[static_cast<std::size_t>(root)], expected) << op.name << " root " << root << " " << describe(Algorithm::Binomial, n, count);
        }
      }
}

TEST(MpiCollectiveResults, AllreduceEqualsTheRankOrderFoldEverywhere) {
  for (Algorithm a : every_algorithm(Collective::Allreduce))
    for (const OpCase& op : op_cases())
      for (int n : rank_counts)
        for (std::size_t count : counts) {
          const std::vector<Bytes> in = inputs_of(op, n, count);
          const Bytes expected = reference_fold(op, in, 0, n, count);
          const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
            Bytes result(count * op.reduction.element_size);
            allreduce(call, in[static_cast<std::size_t>(r)], result, count, op.reduction, a);
            return result;
          });
          for (int r = 0; r < n; ++r)
            ASSERT_EQ(out[static_cast<std::size_t>(r)], expected) << op.name << " rank " << r << " " << describe(a, n, count);
        }
}

// Rank r's block of the result vector is element range [offsets[r], offsets[r+1]).
void check_reduce_scatter(Algorithm a, const OpCase& op, int n, const std::vector<std::size_t>& per_rank, bool block) {
  std::size_t total = 0;
  for (std::size_t c : per_rank) total += c;
  const std::size_t es = op.reduction.element_size;
  const std::vector<Bytes> in = inputs_of(op, n, total);
  const Bytes whole = reference_fold(op, in, 0, n, total);
  const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
    Bytes result(per_rank[static_cast<std::size_t>(r)] * es);
    if (block) reduce_scatter_block(call, in[static_cast<std::size_t>(r)], result, per_rank[0], op.reduction, a);
    else reduce_scatter(call, in[static_cast<std::size_t>(r)], result, per_rank, op.reduction, a);
    return result;
  });
  std::size_t offset = 0;
  for (int r = 0; r < n; ++r) {
    const std::size_t c = per_rank[static_cast<std::size_t>(r)];
    const Bytes expected(whole.begin() + static_cast<std::ptrdiff_t>(offset * es),
                         whole.begin() + static_cast<std::ptrdiff_t>((offset + c) * es));
    EXPECT_EQ(out[static_cast<std::size_t>(r)], expected) << op.name << " rank " << r << " " << describe(a, n, total);
    offset += c;
  }
}

TEST(MpiCollectiveResults, ReduceScatterBlockGivesEachRankItsBlockOfTheFold) {
  for (Algorithm a : every_algorithm(Collective::ReduceScatterBlock))
    for (const OpCase& op : op_cases())
      for (int n : rank_counts)
        for (std::size_t per : {std::size_t{0}, std::size_t{1}, std::size_t{3}})
          check_reduce_scatter(a, op, n, std::vector<std::size_t>(static_cast<std::size_t>(n), per), true);
}

TEST(MpiCollectiveResults, ReduceScatterWithUnequalAndZeroCounts) {
  for (Algorithm a : every_algorithm(Collective::ReduceScatter))
    for (const OpCase& op : op_cases())
      for (int n : rank_counts) {
        std::vector<std::size_t> per(static_cast<std::size_t>(n));
        for (int r = 0; r < n; ++r) per[static_cast<std::size_t>(r)] = static_cast<std::size_t>((r * 5) % 4);
        check_reduce_scatter(a, op, n, per, false);
      }
}

void check_prefix(Algorithm a, const OpCase& op, int n, std::size_t count, bool inclusive) {
  const std::vector<Bytes> in = inputs_of(op, n, count);
  const Bytes untouched(count * op.reduction.element_size, std::byte{0x5A});
  const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
    Bytes result = untouched;
    if (inclusive) scan(call, in[static_cast<std::size_t>(r)], result, count, op.reduction, a);
    else exscan(call, in[static_cast<std::size_t>(r)], result, count, op.reduction, a);
    return result;
  });
  for (int r = 0; r < n; ++r) {
    const int last = inclusive ? r + 1 : r;
    const Bytes expected = last == 0 || count == 0 ? untouched : reference_fold(op, in, 0, last, count);
    EXPECT_EQ(out[static_cast<std::size_t>(r)], expected) << op.name << " rank " << r << " " << describe(a, n, count);
  }
}

TEST(MpiCollectiveResults, ScanIsTheInclusivePrefixInRankOrder) {
  for (Algorithm a : every_algorithm(Collective::Scan))
    for (const OpCase& op : op_cases())
      for (int n : rank_counts)
        for (std::size_t count : counts) check_prefix(a, op, n, count, true);
}

TEST(MpiCollectiveResults, ExscanIsTheExclusivePrefixAndLeavesRankZeroAlone) {
  for (Algorithm a : every_algorithm(Collective::Exscan))
    for (const OpCase& op : op_cases())
      for (int n : rank_counts)
        for (std::size_t count : counts) check_prefix(a, op, n, count, false);
}

// The non-commutative case would pass by luck if the matrices commuted: they must not.
TEST(MpiCollectiveResults, TheMatrixOpReallyDependsOnOrder) {
  const OpCase op = op_cases().back();
  const std::vector<Bytes> in = inputs_of(op, 3, 4);
  const std::vector<Bytes> reversed = {in[2], in[1], in[0]};
  EXPECT_FALSE(op.reduction.commutative);
  EXPECT_NE(reference_fold(op, in, 0, 3, 4), reference_fold(op, reversed, 0, 3, 4));
}

}  // namespace
}  // namespace gcsim::mpi_layer::testing
