#pragma once
// How many all-node exchanges carry a loop's delta form factors (thesis 4.3.1: "each PE
// broadcasts its delta form factors"; 4.4.1: a loop has two synchronizations, the proposals and the
// form factors, "and neither can be removed"). The thesis does not say whether its K = 2 shooters'
// form factors travel in one exchange or in one each:
//  - per-shooter: K exchanges after the proposals (K + 1 per loop), each shooter's on its own.
//  - together: one exchange after the proposals carries every shooter's (2 per loop: the reading
//    of 4.4.1's two synchronizations).
// --aggregate (4.4.3) goes further: no proposals either. Radiosities are identical either way.
#include <string>

namespace gcsim::radiosity {

enum class FormFactorExchange { per_shooter, together };

FormFactorExchange parse_form_factor_exchange(const std::string& s);  // throws std::invalid_argument
const char* to_string(FormFactorExchange e);

}  // namespace gcsim::radiosity
