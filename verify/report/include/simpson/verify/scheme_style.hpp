#pragma once
// How each scheme is drawn, derived from its place in scheme_list: a colour of the palette, a point
// type and a dash type of its own, so that no two schemes look alike, in colour or in grey. Simpson is
// a solid line with small filled circles (a plot against run time scatters its points, and a line
// alone would hide where they are) and its identical twin Lobatto IIIA–IIIB larger hollow circles
// without a line, so where their curves coincide both stay visible: a dot inside a ring.

#include <simpson/scheme.hpp>
#include <simpson/verify/result_model.hpp>

namespace simpson::verify {

struct scheme_style {
  int color;
  int point;
  line_style line;
  int dash = 1;
};

inline scheme_style style_of(scheme_id id) {
  // gnuplot point types: 5 filled square, 7 filled circle, 9 filled triangle, 11 filled inverted
  // triangle, 13 filled diamond, 4 open square, 6 open circle, 8 open triangle.
  // Dash types: 1 solid, 2 dashed, 3 short dashes, 4 dash-dot, 5 dash-dot-dot.
  constexpr int points[] = {5, 7, 9, 11, 13, 4, 6, 8};
  constexpr int dashes[] = {1, 2, 3, 4, 5, 2, 3, 4};
  for (std::size_t k = 0; k < scheme_list.size(); ++k) {
    if (scheme_list[k].id != id) continue;
    if (id == scheme_id::simpson) return {static_cast<int>(k), 7, line_style::lines_points, 1};
    if (id == scheme_id::lobatto_iiia_iiib_3) return {static_cast<int>(k), 6, line_style::points, 1};
    return {static_cast<int>(k), points[k % std::size(points)], line_style::lines_points, dashes[k % std::size(dashes)]};
  }
  return {0, 7, line_style::lines_points};
}

}  // namespace simpson::verify
