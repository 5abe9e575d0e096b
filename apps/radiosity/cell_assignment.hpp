#pragma once
// Which hemicube cells each node computes (thesis 4.3.1, figure 4.1: "the hemicube is cut into a
// mesh and each cell is given to a PE"). The thesis does not say how cells map to PEs:
//  - cyclic: node r takes cells r, r + N, r + 2N, ... in the fixed cell order (top face row by row,
//    then the side faces): every node gets a share of every face, so the work is nearly even;
//  - block: node r takes one contiguous run of cells, [r * C / N, (r + 1) * C / N): a region of the
//    hemicube per node, as the figure draws it. A node whose region sees more of the scene for this
//    shooter works longer, and the others wait at the exchange that follows.
// Either way every cell is computed exactly once and the cells are added in their fixed order, so the
// form factors and radiosities are bit-identical; only the simulated time differs.
#include <string>
#include <vector>

namespace gcsim::radiosity {

enum class CellAssignment { cyclic, block };

CellAssignment parse_cell_assignment(const std::string& s);  // throws std::invalid_argument
const char* to_string(CellAssignment a);

// The cells node `node` of `nodes` computes, in the order it computes them.
std::vector<int> cells_of(CellAssignment a, int node, int nodes, int cells);

}  // namespace gcsim::radiosity
