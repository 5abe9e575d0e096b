#include "apps/radiosity/received_form_factors.hpp"

#include <cstring>
#include <stdexcept>

namespace gcsim::radiosity {
namespace {

constexpr std::size_t kPairBytes = sizeof(std::int32_t) + sizeof(double);

template <class T>
void put(parix::Bytes& out, const T& v) {
  const std::size_t at = out.size();
  out.resize(at + sizeof(T));
  std::memcpy(out.data() + at, &v, sizeof(T));
}

template <class T>
T get(std::span<const std::byte> b, std::size_t& at) {
  if (at + sizeof(T) > b.size()) throw std::runtime_error("radiosity: truncated message");
  T v;
  std::memcpy(&v, b.data() + at, sizeof(T));
  at += sizeof(T);
  return v;
}

}  // namespace

void put_cell_form_factors(parix::Bytes& out, std::int32_t shooter, const CellFormFactors& c) {
  put<std::int32_t>(out, shooter);
  put<std::int32_t>(out, c.cell);
  put<std::int32_t>(out, std::int32_t(c.element.size()));
  for (std::size_t k = 0; k < c.element.size(); ++k) {
    put<std::int32_t>(out, c.element[k]);
    put<double>(out, c.value[k]);
  }
}

void ReceivedFormFactors::reset(int shooters, int cells) {
  shooters_ = shooters, cells_ = cells;
  held_.clear();
  index_.assign(std::size_t(shooters) * std::size_t(cells), Cell{});
}

void ReceivedFormFactors::absorb(parix::Bytes message) {
  index(message);
  held_.push_back(std::move(message));
}

void ReceivedFormFactors::absorb(parix::GatheredBytes shares) {
  for (std::span<const std::byte> share : shares.parts) index(share);
  held_.push_back(std::move(shares.packed));
}

void ReceivedFormFactors::index(std::span<const std::byte> b) {
  std::size_t at = 0;
  while (at < b.size()) {
    const auto k = get<std::int32_t>(b, at);
    const auto cell = get<std::int32_t>(b, at);
    const auto count = get<std::int32_t>(b, at);
    if (k < 0 || k >= shooters_ || cell < 0 || cell >= cells_ || count < 0 ||
        std::size_t(count) * kPairBytes > b.size() - at)
      throw std::runtime_error("radiosity: malformed form factor message");
    index_[std::size_t(k) * std::size_t(cells_) + std::size_t(cell)] = {b.data() + at, count};
    at += std::size_t(count) * kPairBytes;
  }
}

std::int64_t ReceivedFormFactors::add_rows(std::vector<std::vector<double>>& rows) const {
  std::int64_t pairs = 0;
  for (int k = 0; k < shooters_; ++k) {
    std::vector<double>& row = rows[std::size_t(k)];
    for (int c = 0; c < cells_; ++c) {
      const Cell& cell = index_[std::size_t(k) * std::size_t(cells_) + std::size_t(c)];
      for (std::int32_t i = 0; i < cell.count; ++i) {
        std::int32_t element;
        double value;
        std::memcpy(&element, cell.pairs + std::size_t(i) * kPairBytes, sizeof element);
        std::memcpy(&value, cell.pairs + std::size_t(i) * kPairBytes + sizeof element, sizeof value);
        if (element < 0 || std::size_t(element) >= row.size())
          throw std::runtime_error("radiosity: malformed form factor message (element out of range)");
        row[std::size_t(element)] += value;
      }
      pairs += cell.count;
    }
  }
  return pairs;
}

}  // namespace gcsim::radiosity
