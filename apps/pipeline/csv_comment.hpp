#pragma once
// The first row of a CSV a plot reads: what wrote it and on which machine, so the plot's subtitle
// can name them (traces/README.md): "# gcsim accuracy media; machine NAME; nodes 1; model none".
// Readers skip rows that start with '#'.
#include <string>
#include <string_view>

namespace gcsim::pipeline {

// command: e.g. "accuracy media"; nodes and model as they should read ("1-64", "analytic, flow").
std::string csv_comment(std::string_view command, std::string_view machine, std::string_view nodes, std::string_view model);

}  // namespace gcsim::pipeline
