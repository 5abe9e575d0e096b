#pragma once
// The conventional method (thesis section 3.5.1): all form factors first, then the radiosity
// equation (3.11) solved by Gauss-Seidel, per colour channel. With substructuring the unknowns are
// the patch radiosities; the equation then reads
//     B_p = E_p + rho_p * sum_q F_qp (A_q / A_p) B_q,   F_qp = sum over elements e of p of F_qe,
// (F_qe from the hemicube on patch q) and the elements follow as
//     B_e = E_e + rho_e * sum_q F_qe (A_q / A_e) B_q.
// Progressive refinement converges to the same solution, which the tests check.
#include <vector>

#include "apps/radiosity/hemicube.hpp"
#include "apps/radiosity/scene.hpp"

namespace gcsim::radiosity {

struct GaussSeidelResult {
  std::vector<Rgb> element_radiosity;
  std::vector<Rgb> patch_radiosity;
  int iterations = 0;
  double max_change = 0;  // largest change of any B in the last sweep
};

// Throws std::invalid_argument if the full form factor matrix would exceed max_matrix_entries.
GaussSeidelResult solve_gauss_seidel(const Scene& scene, const HemicubeOptions& hemicube, double tolerance = 1e-12,
                                     int max_iterations = 100000, std::size_t max_matrix_entries = 50'000'000);

}  // namespace gcsim::radiosity
