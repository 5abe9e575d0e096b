#pragma once
// The figures of Naruse, Shinya and Saito, tables 1 and 2 (512 x 512 primary rays, 8 x 8
// subregions, sun4/260), copied here so the project never reads them from elsewhere.
// Times are in seconds (the paper prints min'sec"); B1 has no BV column.
#include <array>
#include <string_view>

namespace gcsim::raytrace::paper {

inline constexpr std::array<std::string_view, 5> kPhotos{"photo1", "photo2", "photo3", "photo4", "photo5"};
// Our scene standing for each photo.
inline constexpr std::array<std::string_view, 5> kScenes{"spheres-a", "spheres-b", "spheres-random", "teapot", "teapots"};

struct Table1Row {
  std::string_view algorithm;  // A1 A2 A2' A3 A4 B1
  double seconds[5];
  double bv_per_ray[5];        // negative: not given
  double prim_per_ray[5];
  double total_thousands[5];   // BV + primitive tests over the image, x 10^3
};

inline constexpr std::array<Table1Row, 6> kTable1{{
    {"A1", {2210, 1246, 3318, 739, 1748}, {57.9, 37.9, 86.6, 20.4, 50.9}, {19.8, 6.88, 28.8, 4.61, 9.60}, {20355, 11744, 30245, 6552, 15849}},
    {"A2", {847, 1072, 1278, 522, 1132}, {20.2, 29.7, 30.9, 13.5, 30.5}, {3.75, 5.01, 7.28, 2.53, 4.69}, {6281, 9087, 10008, 4190, 9228}},
    {"A2'", {312, 133, 436, 188, 476}, {3.72, 0.66, 5.68, 2.56, 8.12}, {3.38, 1.61, 4.39, 2.78, 7.04}, {1859, 595, 2640, 1400, 3974}},
    {"A3", {279, 137, 406, 149, 319}, {3.16, 0.65, 5.09, 1.86, 4.88}, {2.27, 1.56, 3.48, 1.60, 3.42}, {1424, 581, 2248, 908, 2174}},
    {"A4", {225, 130, 322, 136, 303}, {1.93, 0.65, 3.18, 1.75, 4.61}, {2.04, 1.79, 2.99, 1.52, 3.20}, {1029, 546, 1608, 893, 2115}},
    {"B1", {415, 171, 574, 149, 366}, {-1, -1, -1, -1, -1}, {7.80, 3.10, 10.8, 2.51, 5.79}, {2045, 813, 2829, 657, 1516}},
}};

// Table 2: A4 time (seconds) against subregion size.
struct Table2Row {
  int tile;
  double seconds[5];
};
inline constexpr std::array<Table2Row, 4> kTable2{{
    {4, {329, 177, 443, 154, 327}},
    {8, {225, 130, 322, 136, 303}},
    {16, {225, 155, 317, 159, 390}},
    {32, {279, 245, 357, 210, 553}},
}};

}  // namespace gcsim::raytrace::paper
