#include "apps/radiosity/form_factor_merge.hpp"

#include <stdexcept>

namespace gcsim::radiosity {

FormFactorMerge parse_form_factor_merge(const std::string& s) {
  if (s == "own-cells") return FormFactorMerge::own_cells;
  if (s == "whole-hemicube") return FormFactorMerge::whole_hemicube;
  throw std::invalid_argument("unknown form factor merge '" + s + "' (expected own-cells or whole-hemicube)");
}

const char* to_string(FormFactorMerge m) { return m == FormFactorMerge::whole_hemicube ? "whole-hemicube" : "own-cells"; }

std::int64_t merge_additions(FormFactorMerge m, int nodes, int cells, int elements) {
  if (m == FormFactorMerge::own_cells || nodes < 2) return 0;
  return std::int64_t(nodes) * std::int64_t(cells) * std::int64_t(elements);
}

}  // namespace gcsim::radiosity
