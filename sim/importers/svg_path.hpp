#pragma once
// SVG path data (the "d" attribute, SVG 1.1 / SVG 2 grammar) to polylines: every command (M L H V Z C S Q T
// A) in absolute and relative form, implicit repeats, compact numbers ("1.5.5" is 1.5 then .5, "-1-2",
// exponents) and arc flags written without separators ("a1 1 0 011 1"). Bezier curves and elliptical arcs
// are flattened into straight pieces, either so that the curve stays within a tolerance of its pieces or
// into a fixed number of pieces. Coordinates stay in the path's user units (y down).

#include <cstddef>
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

struct SvgFlattening {
  /// User units. Above 0: each curve gets as few pieces as keep every point of it within this distance
  /// of them. 0: `curve_segments` pieces.
  double tolerance = 0.0;
  /// Pieces per Bezier curve and per quarter turn of an arc when `tolerance` is 0 (at least 1).
  int curve_segments = 8;
};

/// Points one path may flatten into: more is an error, so no input can make the parser allocate without
/// bound (a tolerance far below the drawing's size asks for millions of pieces).
constexpr std::size_t kSvgPathMaxPoints = 1'000'000;
/// Pieces one curve may be cut into whatever the tolerance.
constexpr int kSvgCurveMaxPieces = 4096;

SvgPathParse parseSvgPath(const std::string& data, const SvgFlattening& flattening);

/// Fixed-count flattening: `curve_segments` pieces per Bezier curve and per quarter turn of an arc.
SvgPathParse parseSvgPath(const std::string& data, int curve_segments = 8);

}  // namespace ifar::sim
