#include "apps/mpi/app/rank_deadlock_report.hpp"

namespace gcsim::mpi_layer::app {
namespace {

void replace_all(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

}  // namespace

std::string rank_deadlock_report(const std::string& report) {
  std::string text = report;
  replace_all(text, "every processor is blocked", "every rank is blocked");
  replace_all(text, "\n  processor ", "\n  rank ");  // the lines parix/sim/deadlock_report.cpp writes
  return text;
}

}  // namespace gcsim::mpi_layer::app
