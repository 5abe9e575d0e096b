#include "apps/mpi/collective_selection.hpp"

#include <optional>
#include <stdexcept>
#include <vector>

namespace gcsim::mpi_layer {
namespace {

using A = Algorithm;
using C = Collective;

constexpr std::array<std::string_view, collective_count> collective_names = {
    "barrier",   "bcast",      "reduce",   "allreduce",      "gather",         "gatherv",
    "scatter",   "scatterv",   "allgather", "allgatherv",    "alltoall",       "alltoallv",
    "reduce_scatter", "reduce_scatter_block", "scan", "exscan"};

constexpr std::array<std::string_view, 12> algorithm_names = {
    "auto",   "dissemination", "binomial", "scatter_allgather", "recursive_doubling", "ring",
    "rabenseifner", "linear", "bruck", "pairwise", "reduce_then_scatter", "recursive_halving"};

constexpr A barrier_algorithms[] = {A::Dissemination};
constexpr A bcast_algorithms[] = {A::Binomial, A::ScatterAllgather};
constexpr A reduce_algorithms[] = {A::Binomial};
constexpr A allreduce_algorithms[] = {A::RecursiveDoubling, A::Ring, A::Rabenseifner};
constexpr A rooted_algorithms[] = {A::Binomial, A::Linear};
constexpr A linear_only[] = {A::Linear};
constexpr A allgather_algorithms[] = {A::Ring, A::RecursiveDoubling, A::Bruck};
constexpr A alltoall_algorithms[] = {A::Pairwise, A::Bruck, A::Linear};
constexpr A alltoallv_algorithms[] = {A::Pairwise, A::Linear};
constexpr A reduce_scatter_algorithms[] = {A::RecursiveHalving, A::Pairwise, A::ReduceThenScatter};
constexpr A scan_algorithms[] = {A::RecursiveDoubling, A::Linear};

bool is_power_of_two(int n) { return n > 0 && (n & (n - 1)) == 0; }

std::optional<Collective> collective_named(std::string_view name) {
  for (std::size_t i = 0; i < collective_count; ++i)
    if (collective_names[i] == name) return static_cast<Collective>(i);
  return std::nullopt;
}

std::string_view trim(std::string_view s) {
  while (!s.empty() && s.front() == ' ') s.remove_prefix(1);
  while (!s.empty() && s.back() == ' ') s.remove_suffix(1);
  return s;
}

std::string known_collectives() {
  std::string out;
  for (std::string_view n : collective_names) out += (out.empty() ? "" : ", ") + std::string(n);
  return out;
}

std::string known_algorithms(Collective c) {
  std::string out = "auto";
  for (Algorithm a : algorithms_of(c)) out += ", " + std::string(algorithm_name(a));
  return out;
}

void parse_item(std::string_view item, AlgorithmChoice& choice) {
  const std::size_t eq = item.find('=');
  if (eq == std::string_view::npos)
    throw std::invalid_argument("collective algorithm spec: '" + std::string(item) +
                                "' is not collective=algorithm (known collectives: " + known_collectives() + ")");
  const std::string_view name = trim(item.substr(0, eq)), algorithm = trim(item.substr(eq + 1));
  const std::optional<Collective> c = collective_named(name);
  if (!c)
    throw std::invalid_argument("collective algorithm spec: unknown collective '" + std::string(name) +
                                "' (known collectives: " + known_collectives() + ")");
  if (algorithm == "auto") return choice.set(*c, A::Auto);
  for (Algorithm a : algorithms_of(*c))
    if (algorithm_name(a) == algorithm) return choice.set(*c, a);
  throw std::invalid_argument("collective algorithm spec: unknown algorithm '" + std::string(algorithm) + "' for " +
                              std::string(name) + " (known: " + known_algorithms(*c) + ")");
}

Algorithm select_allgather(const MessageShape& s) {
  if (s.bytes < allgather_long_msg_size && is_power_of_two(s.ranks)) return A::RecursiveDoubling;
  if (s.bytes < allgather_short_msg_size) return A::Bruck;
  return A::Ring;
}

Algorithm select_alltoall(const MessageShape& s) {
  if (s.bytes <= alltoall_short_msg_size && s.ranks >= 8) return A::Bruck;
  if (s.bytes <= alltoall_medium_msg_size) return A::Linear;
  return A::Pairwise;
}

}  // namespace

std::string_view collective_name(Collective c) { return collective_names[static_cast<std::size_t>(c)]; }
std::string_view algorithm_name(Algorithm a) { return algorithm_names[static_cast<std::size_t>(a)]; }

std::span<const Algorithm> algorithms_of(Collective c) {
  switch (c) {
    case C::Barrier: return barrier_algorithms;
    case C::Bcast: return bcast_algorithms;
    case C::Reduce: return reduce_algorithms;
    case C::Allreduce: return allreduce_algorithms;
    case C::Gather: case C::Scatter: return rooted_algorithms;
    case C::Gatherv: case C::Scatterv: return linear_only;
    case C::Allgather: case C::Allgatherv: return allgather_algorithms;
    case C::Alltoall: return alltoall_algorithms;
    case C::Alltoallv: return alltoallv_algorithms;
    case C::ReduceScatter: case C::ReduceScatterBlock: return reduce_scatter_algorithms;
    case C::Scan: case C::Exscan: return scan_algorithms;
  }
  return {};
}

AlgorithmChoice parse_algorithm_spec(std::string_view spec) {
  AlgorithmChoice choice;
  while (!trim(spec).empty()) {
    const std::size_t comma = spec.find(',');
    const std::string_view item = trim(spec.substr(0, comma));
    if (item.empty()) throw std::invalid_argument("collective algorithm spec: empty item in '" + std::string(spec) + "'");
    parse_item(item, choice);
    spec = comma == std::string_view::npos ? std::string_view{} : spec.substr(comma + 1);
    if (comma != std::string_view::npos && trim(spec).empty())
      throw std::invalid_argument("collective algorithm spec: trailing ','");
  }
  return choice;
}

Algorithm select_algorithm(Collective c, const MessageShape& s) {
  switch (c) {
    case C::Bcast:
      return s.bytes < bcast_short_msg_size || s.ranks < bcast_min_procs ? A::Binomial : A::ScatterAllgather;
    case C::Allreduce: {
      int pof2 = 1;
      while (pof2 * 2 <= s.ranks) pof2 *= 2;
      const bool short_message = s.bytes <= allreduce_short_msg_size || s.count < static_cast<std::size_t>(pof2);
      return short_message || !s.commutative ? A::RecursiveDoubling : A::Rabenseifner;
    }
    case C::Allgather: case C::Allgatherv: return select_allgather(s);
    case C::Alltoall: return select_alltoall(s);
    case C::Alltoallv: return A::Linear;
    case C::ReduceScatter: case C::ReduceScatterBlock:
      if (!s.commutative) return A::ReduceThenScatter;
      return s.bytes < redscat_commutative_long_msg_size ? A::RecursiveHalving : A::Pairwise;
    default: return algorithms_of(c).front();
  }
}

Algorithm resolve_algorithm(Collective c, Algorithm requested, const MessageShape& shape) {
  if (requested == A::Auto) return select_algorithm(c, shape);
  for (Algorithm known : algorithms_of(c))
    if (known == requested) return requested;
  throw std::invalid_argument("collective " + std::string(collective_name(c)) + " has no algorithm '" +
                              std::string(algorithm_name(requested)) + "' (known: " + known_algorithms(c) + ")");
}

}  // namespace gcsim::mpi_layer
