// The data-moving collectives, with every algorithm, on 1..16 ranks, every root, zero and non-zero
// sizes: every rank ends with exactly the bytes the standard says.
#include "tests/mpi_layer/collective_test_support.hpp"

namespace gcsim::mpi_layer::testing {
namespace {

constexpr std::size_t sizes[] = {0, 1, 13, 100};

TEST(MpiCollectiveResults, BcastDeliversTheRootsBufferFromEveryRoot) {
  for (Algorithm a : every_algorithm(Collective::Bcast))
    for (int n : rank_counts)
      for (std::size_t bytes : sizes)
        for (int root = 0; root < n; ++root) {
          const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
            Bytes buffer = r == root ? pattern(root, bytes) : Bytes(bytes);
            bcast(call, buffer, root, a);
            return buffer;
          });
          for (int r = 0; r < n; ++r)
            ASSERT_EQ(out[static_cast<std::size_t>(r)], pattern(root, bytes)) << "root " << root << " " << describe(a, n, bytes);
        }
}

TEST(MpiCollectiveResults, GatherPutsEveryBlockInRankOrderAtTheRoot) {
  for (Algorithm a : every_algorithm(Collective::Gather))
    for (int n : rank_counts)
      for (std::size_t block : sizes)
        for (int root = 0; root < n; ++root) {
          const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
            Bytes result(r == root ? block * static_cast<std::size_t>(n) : 0);
            gather(call, pattern(r, block), result, root, a);
            return result;
          });
          std::vector<Bytes> blocks;
          for (int r = 0; r < n; ++r) blocks.push_back(pattern(r, block));
          ASSERT_EQ(out[static_cast<std::size_t>(root)], concat(blocks)) << "root " << root << " " << describe(a, n, block);
        }
}

TEST(MpiCollectiveResults, ScatterGivesEachRankItsBlockOfTheRoots) {
  for (Algorithm a : every_algorithm(Collective::Scatter))
    for (int n : rank_counts)
      for (std::size_t block : sizes)
        for (int root = 0; root < n; ++root) {
          const Bytes whole = pattern(root, block * static_cast<std::size_t>(n), 3);
          const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
            Bytes result(block);
            scatter(call, r == root ? whole : Bytes{}, result, root, a);
            return result;
          });
          for (int r = 0; r < n; ++r) {
            const auto at = whole.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(r) * block);
            ASSERT_EQ(out[static_cast<std::size_t>(r)], Bytes(at, at + static_cast<std::ptrdiff_t>(block)))
                << "root " << root << " rank " << r << " " << describe(a, n, block);
          }
        }
}

// MPI_IN_PLACE at the root, as the header says: gather's send is the root's own block of result,
// scatter's result the root's own block of send.
TEST(MpiCollectiveResults, GatherAndScatterInPlaceAtTheRoot) {
  for (Algorithm a : every_algorithm(Collective::Gather))
    for (int n : rank_counts)
      for (int root = 0; root < n; ++root) {
        std::vector<Bytes> blocks;
        for (int r = 0; r < n; ++r) blocks.push_back(pattern(r, 6));
        const auto gathered = outputs_of(n, [&](const CollectiveCall& call, int r) {
          if (r != root) {
            gather(call, blocks[static_cast<std::size_t>(r)], {}, root, a);
            return Bytes{};
          }
          Bytes result(6 * static_cast<std::size_t>(n));
          std::copy(blocks[static_cast<std::size_t>(r)].begin(), blocks[static_cast<std::size_t>(r)].end(),
                    result.begin() + 6 * r);
          gather(call, std::span(result).subspan(6 * static_cast<std::size_t>(r), 6), result, root, a);
          return result;
        });
        EXPECT_EQ(gathered[static_cast<std::size_t>(root)], concat(blocks)) << "root " << root << " " << describe(a, n, 6);
        const auto scattered = outputs_of(n, [&](const CollectiveCall& call, int r) {
          Bytes whole = r == root ? concat(blocks) : Bytes{}, mine(6);
          if (r == root) scatter(call, whole, std::span(whole).subspan(6 * static_cast<std::size_t>(r), 6), root, a);
          else scatter(call, {}, mine, root, a);
          return r == root ? whole : mine;
        });
        EXPECT_EQ(scattered[static_cast<std::size_t>(root)], concat(blocks));
        for (int r = 0; r < n; ++r) {
          if (r == root) continue;
          EXPECT_EQ(scattered[static_cast<std::size_t>(r)], blocks[static_cast<std::size_t>(r)]);
        }
      }
}

// Counts r % 3 * 5 bytes (zero for every third rank), placed back to front with gaps.
struct VLayout {
  std::vector<std::size_t> counts, displacements;
  std::size_t bytes = 0;
  explicit VLayout(int n) {
    for (int r = 0; r < n; ++r) counts.push_back(static_cast<std::size_t>(r % 3 * 5));
    displacements.resize(counts.size());
    for (int r = n - 1; r >= 0; --r) {
      displacements[static_cast<std::size_t>(r)] = bytes;
      bytes += counts[static_cast<std::size_t>(r)] + 2;
    }
  }
  Bytes slice(const Bytes& b, int r) const {
    const auto at = b.begin() + static_cast<std::ptrdiff_t>(displacements[static_cast<std::size_t>(r)]);
    return Bytes(at, at + static_cast<std::ptrdiff_t>(counts[static_cast<std::size_t>(r)]));
  }
};

TEST(MpiCollectiveResults, GathervAndScattervHonourCountsAndDisplacements) {
  for (int n : rank_counts) {
    const VLayout v(n);
    for (int root = 0; root < n; ++root) {
      const auto gathered = outputs_of(n, [&](const CollectiveCall& call, int r) {
        Bytes result(r == root ? v.bytes : 0, std::byte{0xEE});
        gatherv(call, pattern(r, v.counts[static_cast<std::size_t>(r)]), result, v.counts, v.displacements, root);
        return result;
      });
      for (int r = 0; r < n; ++r)
        EXPECT_EQ(v.slice(gathered[static_cast<std::size_t>(root)], r), pattern(r, v.counts[static_cast<std::size_t>(r)]));
      const Bytes whole = pattern(root, v.bytes, 9);
      const auto scattered = outputs_of(n, [&](const CollectiveCall& call, int r) {
        Bytes result(v.counts[static_cast<std::size_t>(r)]);
        scatterv(call, r == root ? whole : Bytes{}, v.counts, v.displacements, result, root);
        return result;
      });
      for (int r = 0; r < n; ++r) EXPECT_EQ(scattered[static_cast<std::size_t>(r)], v.slice(whole, r)) << n << " ranks";
    }
  }
}

TEST(MpiCollectiveResults, AllgatherGivesEveryRankEveryBlock) {
  for (Algorithm a : every_algorithm(Collective::Allgather))
    for (int n : rank_counts)
      for (std::size_t block : sizes) {
        std::vector<Bytes> blocks;
        for (int r = 0; r < n; ++r) blocks.push_back(pattern(r, block));
        const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
          Bytes result(block * static_cast<std::size_t>(n));  // in place: own block already there
          std::copy(blocks[static_cast<std::size_t>(r)].begin(), blocks[static_cast<std::size_t>(r)].end(),
                    result.begin() + static_cast<std::ptrdiff_t>(static_cast<std::size_t>(r) * block));
          allgather(call, result, block, a);
          return result;
        });
        for (int r = 0; r < n; ++r) ASSERT_EQ(out[static_cast<std::size_t>(r)], concat(blocks)) << describe(a, n, block);
      }
}

TEST(MpiCollectiveResults, AllgathervWithUnequalBlocksAndGaps) {
  for (Algorithm a : every_algorithm(Collective::Allgatherv))
    for (int n : rank_counts) {
      const VLayout v(n);
      const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
        Bytes result(v.bytes, std::byte{0xEE});
        const Bytes mine = pattern(r, v.counts[static_cast<std::size_t>(r)]);
        std::copy(mine.begin(), mine.end(), result.begin() + static_cast<std::ptrdiff_t>(v.displacements[static_cast<std::size_t>(r)]));
        allgatherv(call, result, v.counts, v.displacements, a);
        return result;
      });
      for (int r = 0; r < n; ++r)
        for (int from = 0; from < n; ++from)
          ASSERT_EQ(v.slice(out[static_cast<std::size_t>(r)], from), pattern(from, v.counts[static_cast<std::size_t>(from)]))
              << "rank " << r << " block " << from << " " << describe(a, n, v.bytes);
    }
}

// Block j of rank i's send is pattern(i * 100 + j): rank j must end with them in order of i.
TEST(MpiCollectiveResults, AlltoallTransposesTheBlocks) {
  for (Algorithm a : every_algorithm(Collective::Alltoall))
    for (int n : rank_counts)
      for (std::size_t block : sizes) {
        const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
          std::vector<Bytes> send;
          for (int j = 0; j < n; ++j) send.push_back(pattern(r * 100 + j, block));
          Bytes result(block * static_cast<std::size_t>(n));
          alltoall(call, concat(send), result, block, a);
          return result;
        });
        for (int j = 0; j < n; ++j) {
          std::vector<Bytes> expected;
          for (int i = 0; i < n; ++i) expected.push_back(pattern(i * 100 + j, block));
          ASSERT_EQ(out[static_cast<std::size_t>(j)], concat(expected)) << "rank " << j << " " << describe(a, n, block);
        }
      }
}

// Rank i sends (i + j) % 4 bytes to rank j; both sides lay blocks out back to front.
TEST(MpiCollectiveResults, AlltoallvHonoursPerPeerCountsOnBothSides) {
  for (Algorithm a : every_algorithm(Collective::Alltoallv))
    for (int n : rank_counts) {
      const auto layout = [n](int me, bool sending) {
        std::pair<std::vector<std::size_t>, std::vector<std::size_t>> l;
        l.first.resize(static_cast<std::size_t>(n)), l.second.resize(static_cast<std::size_t>(n));
        std::size_t at = 0;
        for (int peer = n - 1; peer >= 0; --peer) {
          l.first[static_cast<std::size_t>(peer)] = static_cast<std::size_t>((sending ? me + peer : peer + me) % 4);
          l.second[static_cast<std::size_t>(peer)] = at;
          at += l.first[static_cast<std::size_t>(peer)] + 1;
        }
        return std::pair{l, at};
      };
      const auto out = outputs_of(n, [&](const CollectiveCall& call, int r) {
        const auto [s, send_bytes] = layout(r, true);
        const auto [d, recv_bytes] = layout(r, false);
        Bytes send(send_bytes), result(recv_bytes);
        for (int j = 0; j < n; ++j) {
          const Bytes b = pattern(r * 100 + j, s.first[static_cast<std::size_t>(j)]);
          std::copy(b.begin(), b.end(), send.begin() + static_cast<std::ptrdiff_t>(s.second[static_cast<std::size_t>(j)]));
        }
        alltoallw(call, send, {s.first, s.second}, result, {d.first, d.second}, a);
        Bytes mine;  // the received blocks in order of sender
        for (int i = 0; i < n; ++i) {
          const auto at = result.begin() + static_cast<std::ptrdiff_t>(d.second[static_cast<std::size_t>(i)]);
          mine.insert(mine.end(), at, at + static_cast<std::ptrdiff_t>(d.first[static_cast<std::size_t>(i)]));
        }
        return mine;
      });
      for (int j = 0; j < n; ++j) {
        std::vector<Bytes> expected;
        for (int i = 0; i < n; ++i) expected.push_back(pattern(i * 100 + j, static_cast<std::size_t>((i + j) % 4)));
        ASSERT_EQ(out[static_cast<std::size_t>(j)], concat(expected)) << "rank " << j << " " << describe(a, n, 0);
      }
    }
}

}  // namespace
}  // namespace gcsim::mpi_layer::testing
