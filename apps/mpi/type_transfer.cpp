#include "apps/mpi/type_transfer.hpp"

#include <algorithm>
#include <cstring>

#include "apps/mpi/address.hpp"
#include "apps/mpi/error.hpp"

namespace gcsim::mpi_layer {
namespace {

// Walks the bytes of count elements of a type as blocks of consecutive bytes, in type-map order.
class BlockCursor {
 public:
  BlockCursor(const Datatype& type, MPI_Count count) : type_(type), count_(count) {
    if (type.is_dense() && count > 0) {  // one block for all elements
      dense_bytes_ = type.size() * count;
      count_ = 1;
    }
    skip_empty();
  }
  bool at_end() const { return element_ >= count_; }
  MPI_Aint offset() const {
    const Run& r = type_.runs()[run_];
    return element_ * type_.extent() + r.offset + done_;
  }
  MPI_Count remaining() const { return run_bytes() - done_; }
  void advance(MPI_Count bytes) {
    done_ += bytes;
    if (done_ == run_bytes()) {
      done_ = 0;
      ++run_;
      skip_empty();
    }
  }

 private:
  MPI_Count run_bytes() const {
    if (dense_bytes_ >= 0) return dense_bytes_;
    const Run& r = type_.runs()[run_];
    return r.count * static_cast<MPI_Count>(basic_size(r.basic));
  }
  void skip_empty() {
    if (type_.runs().empty()) element_ = count_;
    if (run_ == type_.runs().size()) {
      run_ = 0;
      ++element_;
    }
  }
  const Datatype& type_;
  MPI_Count count_;
  MPI_Count element_ = 0;
  std::size_t run_ = 0;
  MPI_Count done_ = 0;
  MPI_Count dense_bytes_ = -1;
};

// Walks the signature of count elements of a type: runs of one basic type.
class SignatureCursor {
 public:
  SignatureCursor(const Datatype& type, MPI_Count count) : type_(type), count_(type.has_data() ? count : 0) {}
  bool at_end() const { return element_ >= count_; }
  Basic basic() const { return type_.runs()[run_].basic; }
  MPI_Count remaining() const { return type_.runs()[run_].count - done_; }
  void advance(MPI_Count n) {
    done_ += n;
    if (done_ < type_.runs()[run_].count) return;
    done_ = 0;
    if (++run_ == type_.runs().size()) {
      run_ = 0;
      ++element_;
    }
  }

 private:
  const Datatype& type_;
  MPI_Count count_;
  MPI_Count element_ = 0;
  std::size_t run_ = 0;
  MPI_Count done_ = 0;
};

bool is_packed(const Datatype& t) {
  return t.has_data() && std::all_of(t.runs().begin(), t.runs().end(), [](const Run& r) { return r.basic == Basic::Packed; });
}

}  // namespace

MPI_Count pack_size(MPI_Count count, const Datatype& type) {
  if (count < 0) fail(MPI_ERR_COUNT, "negative count");
  return checked_multiply(count, type.size());
}

std::span<const std::byte> contiguous_bytes(const void* buffer, MPI_Count count, const Datatype& type) {
  if (count <= 0 || !buffer || !type.is_dense()) return {};
  const auto* at = static_cast<const std::byte*>(buffer) + type.runs().front().offset;
  return {at, static_cast<std::size_t>(pack_size(count, type))};
}

void pack(const void* buffer, MPI_Count count, const Datatype& type, std::span<std::byte> out, MPI_Count& position) {
  const MPI_Count bytes = pack_size(count, type);
  if (position < 0 || position > static_cast<MPI_Count>(out.size()) ||
      bytes > static_cast<MPI_Count>(out.size()) - position)
    fail(MPI_ERR_TRUNCATE, "packed data do not fit the output buffer");
  for (BlockCursor c(type, count); !c.at_end(); c.advance(c.remaining())) {
    std::memcpy(out.data() + position, address_at(buffer, c.offset()), static_cast<std::size_t>(c.remaining()));
    position += c.remaining();
  }
}

void unpack(std::span<const std::byte> in, MPI_Count& position, void* buffer, MPI_Count count, const Datatype& type) {
  const MPI_Count bytes = pack_size(count, type);
  if (position < 0 || position > static_cast<MPI_Count>(in.size()) ||
      bytes > static_cast<MPI_Count>(in.size()) - position)
    fail(MPI_ERR_TRUNCATE, "the packed buffer holds fewer bytes than the elements need");
  if (bytes > 0 && type.is_dense()) {  // one block (every message of a predefined type): no cursor
    std::memcpy(address_at(buffer, type.runs().front().offset), in.data() + position, static_cast<std::size_t>(bytes));
    position += bytes;
    return;
  }
  for (BlockCursor c(type, count); !c.at_end(); c.advance(c.remaining())) {
    std::memcpy(address_at(buffer, c.offset()), in.data() + position, static_cast<std::size_t>(c.remaining()));
    position += c.remaining();
  }
}

MPI_Count copy_typed(const void* source, MPI_Count count_from, const Datatype& from, void* destination,
                     MPI_Count count_to, const Datatype& to) {
  MPI_Count copied = 0;
  BlockCursor in(from, count_from), out(to, count_to);
  while (!in.at_end() && !out.at_end()) {
    const MPI_Count n = std::min(in.remaining(), out.remaining());
    std::memmove(address_at(destination, out.offset()), address_at(source, in.offset()), static_cast<std::size_t>(n));
    in.advance(n);
    out.advance(n);
    copied += n;
  }
  return copied;
}

SignatureMatch match_signatures(const Datatype& sent, MPI_Count count_sent, const Datatype& received,
                                MPI_Count count_received) {
  if (is_packed(sent) || is_packed(received)) {
    return sent.size() * count_sent <= received.size() * count_received ? SignatureMatch::Match
                                                                         : SignatureMatch::Truncate;
  }
  SignatureCursor s(sent, count_sent), r(received, count_received);
  while (!s.at_end() && !r.at_end()) {
    if (s.basic() != r.basic()) return SignatureMatch::Mismatch;
    const MPI_Count n = std::min(s.remaining(), r.remaining());
    s.advance(n);
    r.advance(n);
  }
  return s.at_end() ? SignatureMatch::Match : SignatureMatch::Truncate;
}

MPI_Count count_of(MPI_Count bytes, const Datatype& type) {
  if (type.size() == 0) return 0;
  return bytes % type.size() == 0 ? bytes / type.size() : MPI_UNDEFINED;
}

MPI_Count elements_of(MPI_Count bytes, const Datatype& type) {
  if (type.size() == 0) return 0;
  MPI_Count elements = bytes / type.size() * type.elements();
  MPI_Count rest = bytes % type.size();
  for (const Run& r : type.runs()) {
    if (rest == 0) break;
    const auto size = static_cast<MPI_Count>(basic_size(r.basic));
    const MPI_Count whole = std::min(r.count, rest / size);
    elements += whole;
    rest -= whole * size;
    if (whole < r.count) break;
  }
  return rest == 0 ? elements : MPI_UNDEFINED;
}

MPI_Count bytes_of_elements(MPI_Count elements, const Datatype& type) {
  if (elements < 0) fail(MPI_ERR_COUNT, "negative count");
  if (type.elements() == 0) {
    if (elements != 0) fail(MPI_ERR_ARG, "a type without elements holds no elements");
    return 0;
  }
  MPI_Count bytes = checked_multiply(elements / type.elements(), type.size());
  MPI_Count rest = elements % type.elements();
  for (const Run& r : type.runs()) {
    const MPI_Count n = std::min(r.count, rest);
    bytes += n * static_cast<MPI_Count>(basic_size(r.basic));
    rest -= n;
  }
  return bytes;
}

}  // namespace gcsim::mpi_layer
