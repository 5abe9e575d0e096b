#include "apps/pipeline/list_parsing.hpp"

#include <sstream>
#include <stdexcept>
#include <type_traits>

#include <fmt/format.h>

namespace gcsim::pipeline {

namespace {

template <class T>
std::vector<T> parse_list(const std::string& s, const char* what, const char* expected, bool allow_empty = false) {
  std::vector<T> v;
  std::stringstream ss(s);
  std::string item;
  while (std::getline(ss, item, ',')) {
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
  if (v.empty() && !allow_empty) throw std::invalid_argument(fmt::format("{}: empty list", what));
  return v;
}

}  // namespace

std::vector<int> parse_int_list(const std::string& s, const char* what) {
  return parse_list<int>(s, what, "a positive integer (expected e.g. 1,2,4,8)");
}

std::vector<double> parse_double_list(const std::string& s, const char* what) {
  return parse_list<double>(s, what, "a number");
}

std::vector<double> parse_number_list(const std::string& s, const char* what, const char* expected) {
  return parse_list<double>(s, what, expected, true);
}

}  // namespace gcsim::pipeline
