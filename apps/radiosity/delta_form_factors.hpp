#pragma once
// Delta form factors of the hemicube cells (thesis eqs. 3.19 to 3.21) and the fixed partition of the
// hemicube into cells that the parallel algorithms distribute over nodes (section 4.3).
//
// A hemicube of resolution R has a top face of R x R pixels and four side faces of R x R/2 pixels
// (their upper halves). Face coordinates run over [-1, 1] across and, on the sides, [0, 1] upwards.
#include <memory>
#include <vector>

namespace gcsim::radiosity {

enum HemicubeFace { kTopFace = 0, kPlusU = 1, kMinusU = 2, kPlusV = 3, kMinusV = 4 };
inline constexpr int kHemicubeFaces = 5;

class DeltaFormFactors {
 public:
  // resolution must be even and >= 2.
  explicit DeltaFormFactors(int resolution);
  int resolution() const { return r_; }
  int width(int /*face*/) const { return r_; }
  int height(int face) const { return face == kTopFace ? r_ : r_ / 2; }
  // Pixel (i, j) of a face: i across, j up (for the top face j runs along v).
  double at(int face, int i, int j) const { return dff_[face][std::size_t(j) * r_ + i]; }
  const std::vector<double>& face(int f) const { return dff_[f]; }
  // Sum over the pixel rectangle [i0, i1) x [j0, j1) of a face (summed-area table).
  double rect_sum(int face, int i0, int j0, int i1, int j1) const;
  // Sum of the analytic values before normalisation (1 in the limit of fine resolution).
  double raw_total() const { return raw_total_; }

 private:
  int r_;
  double raw_total_ = 0;
  std::vector<double> dff_[kHemicubeFaces];
  std::vector<double> sat_[kHemicubeFaces];  // (w+1) x (h+1)
};

// The tables of one resolution, built once per host process and shared read-only by every
// renderer that asks while another still holds them (all the replicas of a simulated run, the runs
// of a sweep on several threads): they are constants of the method, not state of a node.
std::shared_ptr<const DeltaFormFactors> shared_delta_form_factors(int resolution);

// The hemicube split into cells: the top face into T x T, each side face into T x T/2 rectangles of
// pixels (boundaries rounded down), numbered top face first, then the sides, row by row.
struct HemicubeCell {
  int face;
  int i0, j0, i1, j1;  // pixel rectangle [i0, i1) x [j0, j1)
};
std::vector<HemicubeCell> hemicube_cells(int resolution, int cells_per_side);

}  // namespace gcsim::radiosity
