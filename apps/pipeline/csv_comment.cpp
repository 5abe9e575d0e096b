#include "apps/pipeline/csv_comment.hpp"

#include <fmt/format.h>

namespace gcsim::pipeline {

std::string csv_comment(std::string_view command, std::string_view machine, std::string_view nodes, std::string_view model) {
  // ';' separates the fields: a name that holds one would split, so it becomes ','.
  auto field = [](std::string_view v) {
    std::string s(v);
    for (char& c : s)
      if (c == ';' || c == '\n') c = ',';
    return s;
  };
  return fmt::format("# gcsim {}; machine {}; nodes {}; model {}", field(command), field(machine), field(nodes), field(model));
}

}  // namespace gcsim::pipeline
