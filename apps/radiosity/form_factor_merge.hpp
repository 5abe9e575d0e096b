#pragma once
// How a node adds up the delta form factors an exchange brought it (thesis 4.3.1: "each PE
// broadcasts its delta form factors and so obtains the complete form factors"). The thesis does not
// say how; its tables say what it cost:
//  - own-cells: each part is added over the cells it holds, once (every pair once; no further cost).
//    What a careful implementation does.
//  - whole-hemicube: each of the N parts is added as an array over the whole hemicube, every cell
//    and every element (cells x elements additions per part, N parts per shooter), inside the
//    exchange routine, so it counts as communication. The reading of tables 4.3, 4.5 and 4.8
//    together: the tree broadcast saves the thesis only 5-16 % of a run where table 4.7 makes the
//    broadcast itself 2.5-4x faster, so at 64 nodes at least two thirds of the thesis's
//    communication is work that does not depend on the broadcast's shape; and that work grows in
//    proportion to the nodes (about 15 ms per node per loop from 8 to 64 nodes). A merge over N
//    whole-hemicube arrays is the simplest work with both properties (apps/radiosity/README.md).
//  - fixed-arrays: as whole-hemicube, but each part's array has a fixed kMergeSlots element slots
//    per cell (a program's compile-time maximum; the scene's elements if it has more), so the merge
//    costs the same for every scene that fits. What tables 4.2 and 4.5 say together: per loop,
//    PICROOM (205 elements) and CORNELL (166) communicate within 1 % of each other on 16 and 32
//    nodes, where the merge is most of it. The slots' number is absorbed by a fitted cost per slot.
// Either way the radiosities are bit-identical (the host adds the same pairs); only the simulated
// time differs, charged as the machine's `form_factor_merge` operation.
#include <cstdint>
#include <string>

namespace gcsim::radiosity {

enum class FormFactorMerge { own_cells, whole_hemicube, fixed_arrays };

inline constexpr int kMergeSlots = 256;  // element slots per cell of a fixed-arrays part

FormFactorMerge parse_form_factor_merge(const std::string& s);  // throws std::invalid_argument
const char* to_string(FormFactorMerge m);

// The (cell, element) additions a node makes to merge one shooter's parts from `nodes` nodes:
// 0 for own-cells (charged with the pairs instead), nodes x cells x elements for whole-hemicube,
// nodes x cells x max(elements, kMergeSlots) for fixed-arrays.
std::int64_t merge_additions(FormFactorMerge m, int nodes, int cells, int elements);

}  // namespace gcsim::radiosity
