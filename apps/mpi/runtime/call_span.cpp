#include "apps/mpi/runtime/call_span.hpp"

namespace gcsim::mpi_layer {
namespace {
// An identifier's character in the C locale (isalnum consults the locale on every character).
bool identifier_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}
}  // namespace

std::string_view call_name(std::string_view description) {
  std::size_t n = 0;
  while (n < description.size() && identifier_char(description[n])) ++n;
  return description.substr(0, n);
}

void CallSpan::enter() {
  if (depth_++ > 0) return;
  name_ = {};
  receives_ = sends_ = Peers{};
  sent_ = received_ = 0;
}

void CallSpan::leave() {
  if (depth_ > 0 && --depth_ == 0) name_ = {};  // between calls, records are not a call's
}

void CallSpan::describe(std::string_view description) {
  if (depth_ > 0 && name_.empty()) name_ = owned_.assign(call_name(description));
}

void CallSpan::Peers::add(int p) {
  if (!any) first = p;
  else if (p != first) several = true;
  any = true;
}

void CallSpan::involve(int peer, bool receives) {
  if (depth_ > 0 && peer >= 0) (receives ? receives_ : sends_).add(peer);  // MPI_PROC_NULL, MPI_ANY_SOURCE: none
}

}  // namespace gcsim::mpi_layer
