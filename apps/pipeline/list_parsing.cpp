#include "apps/pipeline/list_parsing.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

namespace gcsim::pipeline {

namespace {

std::vector<std::string> split_at_commas(const std::string& s) {
  std::vector<std::string> items;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) items.push_back(item);
  return items;
}

template <class T>
std::vector<T> parse_items(const std::vector<std::string>& items, const char* what, const char* expected,
                           bool allow_empty = false) {
  std::vector<T> v;
  if (!list_is_empty(items)) {
    for (const std::string& item : items) {
      try {
        std::size_t used = 0;
        T x;
        if constexpr (std::is_integral_v<T>) x = std::stoi(item, &used);
        else x = std::stod(item, &used);
        if (used != item.size() || (std::is_integral_v<T> && x < 1)) throw std::invalid_argument(item);
        v.push_back(x);
      } catch (const std::exception&) {
        throw std::invalid_argument(fmt::format("{}: '{}' is not {}", what, item, expected));
      }
    }
  }
  if (v.empty() && !allow_empty) throw std::invalid_argument(fmt::format("{}: empty list", what));
  return v;
}

constexpr const char* kPositiveInteger = "a positive integer (expected e.g. 1,2,4,8)";

}  // namespace

CLI::Option* add_list_option(CLI::App* cmd, const std::string& name, std::vector<std::string>& items,
                             const std::string& help) {
  return cmd->add_option(name, items, help)->delimiter(',')->allow_extra_args(false);
}

bool list_is_empty(const std::vector<std::string>& items) {
  return std::all_of(items.begin(), items.end(), [](const std::string& i) { return i.empty(); });
}

std::vector<int> parse_int_list(const std::vector<std::string>& items, const char* what) {
  return parse_items<int>(items, what, kPositiveInteger);
}

std::vector<double> parse_double_list(const std::vector<std::string>& items, const char* what) {
  return parse_items<double>(items, what, "a number");
}

std::vector<int> parse_int_list(const std::string& s, const char* what) { return parse_int_list(split_at_commas(s), what); }

std::vector<double> parse_double_list(const std::string& s, const char* what) {
  return parse_double_list(split_at_commas(s), what);
}

std::vector<double> parse_number_list(const std::string& s, const char* what, const char* expected) {
  return parse_items<double>(split_at_commas(s), what, expected, true);
}

}  // namespace gcsim::pipeline
