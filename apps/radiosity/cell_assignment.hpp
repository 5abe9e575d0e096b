#pragma once
// Which hemicube cells each node computes (thesis 4.3.1, figure 4.1: "the hemicube is cut into a
// mesh and each cell is given to a PE"). The thesis does not say how cells map to PEs:
//  - cyclic: node r takes cells r, r + N, r + 2N, ... in the partition's order (top face row by row,
//    then the side faces): every node gets a share of every face, so the work is nearly even;
//  - block: node r takes one contiguous run of the partition's order, [r * C / N, (r + 1) * C / N): a
//    region of the hemicube per node, as the figure draws it. A node whose region sees more of the
//    scene for this shooter works longer, and the others wait at the exchange that follows.
// Nor does it say how the side faces are laid out in the mesh it cuts (SideFaces):
//  - half: each side face is the T x T/2 cells above the shooter's horizon, as the hemicube's
//    definition has it: 3 T^2 positions;
//  - full: each side face is a whole T x T square whose lower half, below the horizon, sees nothing
//    (the five images of a program that renders the hemicube as five equal Z-buffer frames): 5 T^2
//    positions, T^2 / 2 of each side face empty. A side face's rows run in raster order, the top row
//    (next to the top face) first and the empty half last, as a frame whose up is the shooter's
//    normal is stored. A node whose run falls on empty positions has less work.
// Either way every cell is computed exactly once and the cells are added in their fixed order, so the
// form factors and radiosities are bit-identical; only the simulated time differs.
#include <string>
#include <vector>

namespace gcsim::radiosity {

enum class CellAssignment { cyclic, block };
enum class SideFaces { half, full };

CellAssignment parse_cell_assignment(const std::string& s);  // throws std::invalid_argument
const char* to_string(CellAssignment a);
SideFaces parse_side_faces(const std::string& s);  // throws std::invalid_argument
const char* to_string(SideFaces s);

// The cells node `node` of `nodes` computes, in the order it computes them, of a partition of
// `cells` cells. With SideFaces::full, `cells` must be 3 T^2 for an even T (the hemicube's
// partition: hemicube_cells); throws std::invalid_argument otherwise.
std::vector<int> cells_of(CellAssignment a, int node, int nodes, int cells, SideFaces s = SideFaces::half);

}  // namespace gcsim::radiosity
