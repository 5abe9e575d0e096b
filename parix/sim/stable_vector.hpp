#pragma once
// A growable array whose elements never move, so references stay valid while it grows (the
// simulation's link ends: a process holds one while a connect adds more). Elements live in chunks
// of 2^kBits, so an index is a shift and a mask; std::deque, which gave the same stability, pays
// a division per index, and a link end is looked up twice per message.
#include <cstddef>
#include <memory>
#include <stdexcept>
#include <vector>

namespace gcsim::parix {

template <typename T, unsigned kBits = 6>
class StableVector {
 public:
  std::size_t size() const { return size_; }
  T& operator[](std::size_t i) { return chunks_[i >> kBits][i & kMask]; }
  const T& operator[](std::size_t i) const { return chunks_[i >> kBits][i & kMask]; }
  T& at(std::size_t i) {
    if (i >= size_) throw std::out_of_range("StableVector::at");
    return (*this)[i];
  }
  // Appends a default-constructed element (constructed with its chunk) and returns it.
  T& emplace_back() {
    if ((size_ >> kBits) == chunks_.size()) chunks_.push_back(std::make_unique<T[]>(kChunk));
    return (*this)[size_++];
  }

 private:
  static constexpr std::size_t kChunk = std::size_t{1} << kBits;
  static constexpr std::size_t kMask = kChunk - 1;
  std::vector<std::unique_ptr<T[]>> chunks_;
  std::size_t size_ = 0;
};

}  // namespace gcsim::parix
