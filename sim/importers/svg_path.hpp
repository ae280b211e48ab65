#pragma once
// SVG path data ("d" attribute) to polylines: M/L/H/V/Z, cubic and quadratic Bezier curves (C/S/Q/T,
// flattened), absolute and relative forms, implicit repeated commands. Elliptical arcs (A) are not
// supported and reported as such. Coordinates stay in SVG user units (y down).

#include <string>
#include <vector>

#include "common/geometry/point.hpp"

namespace ifar::sim {

struct SvgSubpath {
  std::vector<geometry::Point> points;  // as drawn, including a repeated first point if the data has one
  bool closed = false;                  // ended by Z/z
};

struct SvgPathParse {
  std::vector<SvgSubpath> subpaths;
  std::string error;  // "at character N: problem" when the data is malformed
};

/// `curve_segments`: straight pieces per Bezier curve.
SvgPathParse parseSvgPath(const std::string& data, int curve_segments = 8);

}  // namespace ifar::sim
