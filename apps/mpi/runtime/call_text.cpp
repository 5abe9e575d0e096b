// Formatting an operation's call (operation.hpp), done only when a text is needed.
#include <charconv>

#include "apps/mpi/runtime/operation.hpp"
#include "apps/mpi/runtime/rank.hpp"

namespace gcsim::mpi_layer {
namespace {

void append_number(std::string& text, int value) {
  char digits[16];
  const auto end = std::to_chars(digits, digits + sizeof digits, value).ptr;
  text.append(digits, end);
}

}  // namespace

void CallText::append_to(std::string& out) const {
  if (form == Form::text) {
    if (text) out.append(*text);
    return;
  }
  if (form == Form::collective_receive) {
    out.append("a collective's receive from rank ");
    append_number(out, peer);
    return;
  }
  out.append(name).append("(").append(peer_label).append("=");
  if (peer == MPI_ANY_SOURCE) out.append("MPI_ANY_SOURCE");
  else append_number(out, peer);
  out.append(", tag=");
  if (tag == MPI_ANY_TAG) out.append("MPI_ANY_TAG");
  else append_number(out, tag);
  out.append(", comm=").append(Rank::comm_name(comm)).append(")");
}

std::string CallText::str() const {
  std::string out;
  append_to(out);
  return out;
}

}  // namespace gcsim::mpi_layer
