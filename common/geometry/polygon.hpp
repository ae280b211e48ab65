#pragma once
// Simple polygons as vertex lists (not closed: the last vertex connects back to the first).

#include <vector>

#include <Eigen/Geometry>

#include "common/geometry/point.hpp"
#include "common/geometry/segment.hpp"

namespace ifar::geometry {

using Polygon = std::vector<Point>;

/// Shoelace area: positive for counter-clockwise vertex order, 0 for fewer than 3 vertices.
double signedArea(const Polygon& polygon);
double area(const Polygon& polygon);
/// The smallest axis-aligned box holding every vertex (empty for no vertices).
Eigen::AlignedBox2d boundingBox(const Polygon& polygon);
Point centroid(const Polygon& polygon);
double perimeter(const Polygon& polygon);

/// Edge i runs from vertex i to vertex (i + 1) % n.
Segment polygonEdge(const Polygon& polygon, std::size_t index);

/// Counter-clockwise order (reversed copy when clockwise).
Polygon counterClockwise(Polygon polygon);

enum class Containment { Outside, Boundary, Inside };
/// Where `point` lies relative to the polygon, with points within kEpsilon of an edge on the Boundary.
Containment locatePoint(const Polygon& polygon, const Point& point);
/// True for Inside or Boundary.
bool containsPoint(const Polygon& polygon, const Point& point);

/// True when no three consecutive vertices turn both ways; collinear vertices are allowed.
/// False for fewer than 3 vertices or zero area.
bool isConvex(const Polygon& polygon);
/// True when no two non-adjacent edges touch and adjacent edges meet only at their shared vertex.
bool isSimple(const Polygon& polygon);

/// Convex hull, counter-clockwise, without collinear vertices (Andrew's monotone chain).
Polygon convexHull(std::vector<Point> points);

/// The polygon's width: the minimum distance between two parallel supporting lines, by rotating
/// calipers over the convex hull. 0 for fewer than 3 non-collinear points.
double width(const Polygon& polygon);

/// Distance from `point` to the polygon's boundary (0 on it).
double distanceToBoundary(const Polygon& polygon, const Point& point);

/// A counter-clockwise polygon with every edge moved `distance` outward (inward when negative), its
/// corners mitred, the mitre capped at twice `distance` (a sharp spike is cut back, not stretched).
/// Meant for offsets smaller than the polygon's edges: a longer one can fold an edge back; check the
/// result with isSimple() where that matters.
Polygon offsetPolygon(const Polygon& polygon, double distance);

/// True when the polygons' closed regions share a point (touching counts).
bool polygonsIntersect(const Polygon& first, const Polygon& second);

}  // namespace ifar::geometry
