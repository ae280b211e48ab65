#pragma once
// 2-D points and vectors are Eigen::Vector2d throughout the project; this header names them and the
// tolerance geometric predicates use.

#include <Eigen/Core>

namespace ifar::geometry {

using Point = Eigen::Vector2d;
using Vector = Eigen::Vector2d;

/// Absolute tolerance in metres for "on the line" / "touching" decisions.
constexpr double kEpsilon = 1e-9;

/// z of the 3-D cross product (b - a) x (c - a): > 0 when a, b, c turn counter-clockwise.
inline double cross(const Point& a, const Point& b, const Point& c)
{
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

/// z of u x v.
inline double cross(const Vector& u, const Vector& v)
{
  return u.x() * v.y() - u.y() * v.x();
}

}  // namespace ifar::geometry
