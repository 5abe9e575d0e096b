#include "apps/radiosity/form_factor_merge.hpp"

#include <algorithm>
#include <stdexcept>

namespace gcsim::radiosity {

FormFactorMerge parse_form_factor_merge(const std::string& s) {
  if (s == "own-cells") return FormFactorMerge::own_cells;
  if (s == "whole-hemicube") return FormFactorMerge::whole_hemicube;
  if (s == "fixed-arrays") return FormFactorMerge::fixed_arrays;
  throw std::invalid_argument("unknown form factor merge '" + s + "' (expected own-cells, whole-hemicube or fixed-arrays)");
}

const char* to_string(FormFactorMerge m) {
  switch (m) {
    case FormFactorMerge::whole_hemicube: return "whole-hemicube";
    case FormFactorMerge::fixed_arrays: return "fixed-arrays";
    case FormFactorMerge::own_cells: break;
  }
  return "own-cells";
}

std::int64_t merge_additions(FormFactorMerge m, int nodes, int cells, int elements) {
  if (m == FormFactorMerge::own_cells || nodes < 2) return 0;
  const int slots = m == FormFactorMerge::fixed_arrays ? std::max(elements, kMergeSlots) : elements;
  return std::int64_t(nodes) * std::int64_t(cells) * std::int64_t(slots);
}

}  // namespace gcsim::radiosity
