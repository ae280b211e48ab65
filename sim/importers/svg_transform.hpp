#pragma once
// SVG `transform` attributes: a list of matrix(a b c d e f), translate(tx [ty]), scale(sx [sy]),
// rotate(angle [cx cy]), skewX(angle) and skewY(angle) (degrees), applied right to left as SVG 1.1
// section 7.6 says: "translate(10) scale(2)" scales first. An element's user space is its parent's
// composed with its own list, down from the root.

#include <optional>
#include <string>

#include <Eigen/Geometry>

#include "common/geometry/point.hpp"

namespace ifar::sim {

using SvgTransform = Eigen::Affine2d;

struct SvgTransformParse {
  SvgTransform transform = SvgTransform::Identity();
  std::string error;  // "at character N: problem"
};

SvgTransformParse parseSvgTransform(const std::string& text);

/// The largest factor by which the transform stretches a length (its linear part's largest singular
/// value): a distance of d in the element's units is at most this times d in the root's.
double largestStretch(const SvgTransform& transform);

}  // namespace ifar::sim
