#pragma once
// The letters ranks exchange (rank.cpp's protocol, rank_cancel.cpp's withdrawal of a send): each
// carries a kind and four words.
#include <cstdint>

#include "parix/mailbox.hpp"

namespace gcsim::mpi_layer {

enum LetterKind : std::int64_t {
  kEager = 1,
  kRequestToSend = 2,
  kClearToSend = 3,
  kData = 4,
  kCancelAsk = 5,     // the sender asks the receiver to drop its request-to-send
  kCancelAnswer = 6,  // the receiver says whether it did (third word 1) or had matched it (0)
};

// words: [0] kind | size << 8, [1] context, [2] tag, the receiver's operation or the answer,
// [3] the sender's operation.
inline parix::Envelope envelope(LetterKind kind, std::int64_t size, std::int64_t context, std::int64_t third,
                                std::int64_t fourth) {
  parix::Envelope e;
  e.words = {kind | (size << 8), context, third, fourth};
  return e;
}

}  // namespace gcsim::mpi_layer
