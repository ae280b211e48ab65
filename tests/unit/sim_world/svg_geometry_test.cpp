// SVG geometry as the namosim importer reads it: the path grammar (numbers, every command, arcs), curve
// flattening to a tolerance, transforms and the basic shapes.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "common/geometry/polygon.hpp"
#include "sim/importers/svg_arc.hpp"
#include "sim/importers/svg_document.hpp"
#include "sim/importers/svg_number.hpp"
#include "sim/importers/svg_path.hpp"
#include "sim/importers/svg_shapes.hpp"
#include "sim/importers/svg_transform.hpp"
#include "sim/importers/xml_elements.hpp"

namespace ifar::sim {
namespace {

using geometry::Point;

constexpr double kPi = 3.14159265358979323846;

SvgPathParse parseFine(const std::string& data, double tolerance = 1e-3)
{
  SvgFlattening flattening;
  flattening.tolerance = tolerance;
  return parseSvgPath(data, flattening);
}

TEST(SimWorldXmlElements, ElementsInDocumentOrderWithParentsLinesAndEntities)
{
  const XmlScan scan = scanXmlElements(
      "<?xml version=\"1.0\"?>\n<!-- a comment <g> -->\n<svg:svg a=\"&lt;&amp;&#65;\">\n"
      "  <g id=\"outer\">\n    <path id=\"p\"/>\n    <![CDATA[ <path id=\"no\"/> ]]>\n  </g>\n  "
      "<rect/>\n</svg:svg>");
  ASSERT_TRUE(scan.error.empty()) << scan.error;
  ASSERT_EQ(scan.elements.size(), 4u);
  EXPECT_EQ(scan.elements[0].localName(), "svg");
  EXPECT_EQ(scan.elements[0].attribute("a"), "<&A");
  EXPECT_EQ(scan.elements[0].parent, -1);
  EXPECT_EQ(scan.elements[1].attribute("id"), "outer");
  EXPECT_EQ(scan.elements[1].line, 4);
  EXPECT_EQ(scan.elements[2].attribute("id"), "p");
  EXPECT_EQ(scan.elements[2].parent, 1);
  EXPECT_EQ(scan.elements[2].line, 5);
  EXPECT_EQ(scan.elements[3].name, "rect");
  EXPECT_EQ(scan.elements[3].parent, 0);
}

TEST(SimWorldXmlElements, MalformedOrTooDeepMarkupIsOneLine)
{
  EXPECT_EQ(scanXmlElements("<svg a=\"1\" a=\"2\"/>").error,
            "line 1: element <svg>: an attribute cannot be read (a value not quoted or not closed, or a name "
            "repeated)");
  EXPECT_EQ(scanXmlElements("<svg>\n<!-- open").error, "line 2: comment not closed (missing '-->')");
  EXPECT_EQ(scanXmlElements("").error, "line 0: no element in the document");
  std::string deep;
  for (int level = 0; level < 300; ++level) {
    deep += "<g>";
  }
  for (int level = 0; level < 300; ++level) {
    deep += "</g>";
  }
  EXPECT_EQ(scanXmlElements(deep).error, "line 1: elements nested more than 256 deep");
  EXPECT_TRUE(scanXmlElements(deep).elements.empty());
}

TEST(SimWorldSvgNumber, ReadsCompactSvgNumbers)
{
  const auto numbers = parseSvgNumberList("1.5.5-1-2 1e1,2E-1+3 .25e+1");
  ASSERT_TRUE(numbers);
  ASSERT_EQ(numbers->size(), 8u);
  EXPECT_EQ((*numbers)[0], 1.5);
  EXPECT_EQ((*numbers)[1], 0.5);
  EXPECT_EQ((*numbers)[2], -1.0);
  EXPECT_EQ((*numbers)[3], -2.0);
  EXPECT_EQ((*numbers)[4], 10.0);
  EXPECT_EQ((*numbers)[5], 0.2);
  EXPECT_EQ((*numbers)[6], 3.0);
  EXPECT_EQ((*numbers)[7], 2.5);
  EXPECT_FALSE(parseSvgNumberList("1 2 x"));
  EXPECT_FALSE(parseSvgNumberList("1e999"));  // out of the range of a double
}

TEST(SimWorldSvgPath, CompactSyntaxAndImplicitRepeats)
{
  const auto parse = parseSvgPath("M1.5.5L-1-2 3,4h1v.5 2zm1 1 1 0 0 1");
  ASSERT_TRUE(parse.error.empty()) << parse.error;
  ASSERT_EQ(parse.subpaths.size(), 2u);
  const auto& first = parse.subpaths[0].points;
  ASSERT_EQ(first.size(), 6u);
  EXPECT_EQ(first[0], Point(1.5, 0.5));
  EXPECT_EQ(first[1], Point(-1, -2));
  EXPECT_EQ(first[2], Point(3, 4));  // implicit repeat of L
  EXPECT_EQ(first[3], Point(4, 4));
  EXPECT_EQ(first[4], Point(4, 4.5));
  EXPECT_EQ(first[5], Point(4, 6.5));  // implicit repeat of v
  EXPECT_TRUE(parse.subpaths[0].closed);
  // After z the pen is back at (1.5, 0.5): the relative moveto starts there, its pairs are linetos.
  const auto& second = parse.subpaths[1].points;
  ASSERT_EQ(second.size(), 3u);
  EXPECT_EQ(second[0], Point(2.5, 1.5));
  EXPECT_EQ(second[1], Point(3.5, 1.5));
  EXPECT_EQ(second[2], Point(3.5, 2.5));
  EXPECT_FALSE(parse.subpaths[1].closed);
}

TEST(SimWorldSvgPath, SmoothCurvesReflectTheLastControlPoint)
{
  // S after C reflects C's second control point; the curve through (0,0) (5,5) (10,0) ... is symmetric.
  const auto parse = parseSvgPath("M 0 0 C 0 10 10 10 10 0 S 20 -10 20 0 Q 25 10 30 0 T 40 0", 2);
  ASSERT_TRUE(parse.error.empty()) << parse.error;
  const auto& points = parse.subpaths.at(0).points;
  ASSERT_EQ(points.size(), 9u);
  EXPECT_NEAR(points[1].x(), 5.0, 1e-12);
  EXPECT_NEAR(points[1].y(), 7.5, 1e-12);
  EXPECT_NEAR(points[3].x(), 15.0, 1e-12);  // reflected control (10,-10): the mirror image of the first curve
  EXPECT_NEAR(points[3].y(), -7.5, 1e-12);
  EXPECT_NEAR(points[5].y(), 5.0, 1e-12);   // quadratic midpoint: half the control height
  EXPECT_NEAR(points[7].y(), -5.0, 1e-12);  // T reflects Q's control to (35, -10)
  EXPECT_EQ(points[8], Point(40, 0));
}

TEST(SimWorldSvgArc, CentreParameterisationFollowsTheFlags)
{
  // Quarter circle from (0,0) to (1,1), radius 1, small arc, positive sweep: centre (0,1).
  const SvgArcCentre small = svgArcCentre(Point(0, 0), 1, 1, 0, false, true, Point(1, 1));
  EXPECT_NEAR(small.centre.x(), 0.0, 1e-12);
  EXPECT_NEAR(small.centre.y(), 1.0, 1e-12);
  EXPECT_NEAR(small.sweep_angle, 0.5 * kPi, 1e-12);
  // The large arc with the same sweep goes round the other centre, (1,0), three quarters of a turn.
  const SvgArcCentre large = svgArcCentre(Point(0, 0), 1, 1, 0, true, true, Point(1, 1));
  EXPECT_NEAR(large.centre.x(), 1.0, 1e-12);
  EXPECT_NEAR(large.centre.y(), 0.0, 1e-12);
  EXPECT_NEAR(large.sweep_angle, 1.5 * kPi, 1e-12);
  // Radii too small for the chord are scaled up until the ellipse just reaches: a half turn about the
  // chord's midpoint, keeping their 1:2 ratio.
  const SvgArcCentre scaled = svgArcCentre(Point(0, 0), 1, 2, 0, false, false, Point(20, 0));
  EXPECT_NEAR(scaled.radius_x, 10.0, 1e-12);
  EXPECT_NEAR(scaled.radius_y, 20.0, 1e-12);
  EXPECT_NEAR(scaled.centre.x(), 10.0, 1e-12);
  EXPECT_NEAR(scaled.centre.y(), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(scaled.sweep_angle), kPi, 1e-12);
  // A rotated ellipse: every sample lies on it.
  const SvgArcCentre rotated = svgArcCentre(Point(3, 1), 4, 2, 30, false, true, Point(-1, 2));
  for (int step = 0; step <= 8; ++step) {
    const Point sample = rotated.pointAt(rotated.start_angle + rotated.sweep_angle * step / 8.0);
    const Point local = Eigen::Rotation2Dd(-rotated.rotation) * (sample - rotated.centre);
    EXPECT_NEAR(std::pow(local.x() / rotated.radius_x, 2) + std::pow(local.y() / rotated.radius_y, 2), 1.0,
                1e-12);
  }
  EXPECT_NEAR((rotated.pointAt(rotated.start_angle + rotated.sweep_angle) - Point(-1, 2)).norm(), 0.0, 1e-12);
}

TEST(SimWorldSvgPath, ArcsWithCompactFlagsZeroRadiiAndNoLength)
{
  // "a1 1 0 011 1": radii 1 1, rotation 0, flags 0 and 1, end (1,1) relative: the quarter circle about (0,1).
  const auto quarter = parseSvgPath("M0 0a1 1 0 011 1", 4);
  ASSERT_TRUE(quarter.error.empty()) << quarter.error;
  const auto& points = quarter.subpaths.at(0).points;
  ASSERT_EQ(points.size(), 5u);  // 4 pieces per quarter turn
  EXPECT_NEAR(points[2].x(), std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(points[2].y(), 1.0 - std::sqrt(0.5), 1e-12);
  EXPECT_EQ(points[4], Point(1, 1));
  // A zero radius draws a line; an arc to the current point draws nothing.
  const auto line = parseSvgPath("M 0 0 A 0 5 0 0 1 20 0 A 5 5 0 0 1 20 0");
  ASSERT_TRUE(line.error.empty()) << line.error;
  ASSERT_EQ(line.subpaths.at(0).points.size(), 2u);
  EXPECT_EQ(line.subpaths[0].points[1], Point(20, 0));
  // A semicircle with positive sweep passes above the chord in SVG's y-down frame (y = -10).
  const auto half = parseSvgPath("M 0 0 A 10 10 0 0 1 20 0", 2);
  ASSERT_EQ(half.subpaths.at(0).points.size(), 5u);
  EXPECT_NEAR(half.subpaths[0].points[2].x(), 10.0, 1e-12);
  EXPECT_NEAR(half.subpaths[0].points[2].y(), -10.0, 1e-12);
  EXPECT_EQ(parseSvgPath("M 0 0 a 1 1 0 0 1").error, "at character 17: command 'a' expects 2 numbers");
}

TEST(SimWorldSvgPath, CurvesStayWithinTheTolerance)
{
  // A circle of radius 10 from two arcs at tolerance 0.1: each half turn needs ceil(pi / 2 acos(0.99)) = 12
  // pieces; every chord's midpoint is within 0.1 of the circle.
  const auto circle = parseFine("M 10 0 A 10 10 0 0 1 -10 0 A 10 10 0 0 1 10 0 Z", 0.1);
  ASSERT_TRUE(circle.error.empty()) << circle.error;
  const auto& ring = circle.subpaths.at(0).points;
  ASSERT_EQ(ring.size(), 25u);
  for (std::size_t index = 0; index + 1 < ring.size(); ++index) {
    EXPECT_NEAR(ring[index].norm(), 10.0, 1e-9);
    const double gap = 10.0 - (0.5 * (ring[index] + ring[index + 1])).norm();
    EXPECT_GT(gap, 0.0);
    EXPECT_LE(gap, 0.1);
  }
  // A cubic: the polyline's distance from 1000 samples of the curve stays within the tolerance.
  const Point p0(0, 0), p1(0, 40), p2(60, 40), p3(60, 0);
  const auto cubic = parseFine("M 0 0 C 0 40 60 40 60 0", 0.05);
  const auto& polyline = cubic.subpaths.at(0).points;
  EXPECT_GT(polyline.size(), 10u);
  EXPECT_LT(polyline.size(), 60u);
  for (int sample = 0; sample <= 1000; ++sample) {
    const double t = sample / 1000.0;
    const double u = 1.0 - t;
    const Point on_curve = u * u * u * p0 + 3 * u * u * t * p1 + 3 * u * t * t * p2 + t * t * t * p3;
    double nearest = 1e9;
    for (std::size_t index = 0; index + 1 < polyline.size(); ++index) {
      nearest = std::min(nearest, geometry::distanceToSegment(
                                      on_curve, geometry::Segment{polyline[index], polyline[index + 1]}));
    }
    EXPECT_LE(nearest, 0.05) << "t = " << t;
  }
}

TEST(SimWorldSvgPath, FlatteningIsBounded)
{
  // A tolerance far below the drawing's size asks for more points than any path may have.
  const std::string many_arcs = [] {
    std::string data = "M 0 0";
    for (int index = 0; index < 400; ++index) {
      data += " A 1e6 1e6 0 1 1 " + std::to_string(index % 2 == 0 ? 1 : 0) + " 0";
    }
    return data;
  }();
  const auto parse = parseFine(many_arcs, 1e-6);
  EXPECT_NE(parse.error.find("points after flattening the curves"), std::string::npos) << parse.error;
  EXPECT_TRUE(parse.subpaths.empty());
}

TEST(SimWorldSvgTransform, ParsesEveryTransformAndComposesRightToLeft)
{
  const auto apply = [](const std::string& text, const Point& point) {
    const SvgTransformParse parsed = parseSvgTransform(text);
    EXPECT_TRUE(parsed.error.empty()) << text << ": " << parsed.error;
    return Point(parsed.transform * point);
  };
  const auto near = [](const Point& actual, const Point& expected) {
    return (actual - expected).norm() < 1e-12;
  };
  EXPECT_TRUE(near(apply("translate(10) scale(2)", Point(1, 1)), Point(12, 2)));
  EXPECT_TRUE(near(apply("scale(2) translate(10)", Point(1, 1)), Point(22, 2)));
  EXPECT_TRUE(near(apply("rotate(90)", Point(1, 0)), Point(0, 1)));
  EXPECT_TRUE(near(apply("rotate(90 10 10)", Point(20, 10)), Point(10, 20)));
  EXPECT_TRUE(near(apply("matrix(1 2 3 4 5 6)", Point(1, 1)), Point(9, 12)));
  EXPECT_TRUE(near(apply("skewX(45)", Point(0, 1)), Point(1, 1)));
  EXPECT_TRUE(near(apply("skewY(45)", Point(1, 0)), Point(1, 1)));
  EXPECT_TRUE(near(apply(" translate(1,2),scale(3 , 4) ", Point(1, 1)), Point(4, 6)));
  EXPECT_NEAR(largestStretch(parseSvgTransform("rotate(30) scale(3, 0.5)").transform), 3.0, 1e-12);
  EXPECT_EQ(parseSvgTransform("translate(5").error,
            "at character 11: 'translate(' needs numbers and a closing ')'");
  EXPECT_EQ(
      parseSvgTransform("shear(1)").error,
      "at character 0: 'shear' with 1 numbers is not an SVG transform (matrix 6, translate 1-2, scale 1-2, "
      "rotate 1 or 3, skewX/skewY 1)");
  EXPECT_EQ(parseSvgTransform("10").error,
            "at character 0: expected a transform name (matrix, translate, scale, rotate, skewX, skewY)");
}

double outlineArea(const std::string& element)
{
  const auto parsed = SvgDocument::parse("<svg viewBox=\"0 0 100 100\">" + element + "</svg>");
  EXPECT_TRUE(parsed.document) << parsed.error;
  const SvgPathParse outline = parsed.document->outline(1, 1e-4);
  EXPECT_TRUE(outline.error.empty()) << outline.error;
  EXPECT_EQ(outline.subpaths.size(), 1u) << element;
  return outline.subpaths.empty() ? 0.0 : geometry::area(outline.subpaths[0].points);
}

TEST(SimWorldSvgShapes, BasicShapesAsTheirPathEquivalents)
{
  EXPECT_NEAR(outlineArea("<rect x=\"1\" y=\"2\" width=\"10\" height=\"5\"/>"), 50.0, 1e-12);
  // Rounded corners: a missing ry takes rx; the four corners make one circle of radius 2.
  EXPECT_NEAR(outlineArea("<rect width=\"10\" height=\"5\" rx=\"2\"/>"), 50.0 - (4.0 - kPi) * 4.0, 1e-3);
  EXPECT_NEAR(outlineArea("<circle cx=\"50\" cy=\"50\" r=\"10px\"/>"), kPi * 100.0, 0.05);
  EXPECT_NEAR(outlineArea("<ellipse cx=\"50\" cy=\"50\" rx=\"10\" ry=\"4\"/>"), kPi * 40.0, 0.05);
  EXPECT_NEAR(outlineArea("<polygon points=\"0,0 10,0 10,10\"/>"), 50.0, 1e-12);
  EXPECT_NEAR(outlineArea("<path d=\"M0 0H4V4\" transform=\"scale(2 3)\"/>"), 0.5 * 8 * 12, 1e-12);
  std::string error;
  EXPECT_FALSE(svgShapePathData(XmlElement{"circle", {{"r", "2cm"}}, 1, -1}, error));
  EXPECT_EQ(error, "attribute 'r' is not a length in user units: '2cm'");
  EXPECT_FALSE(svgShapePathData(XmlElement{"polyline", {{"points", "0 0 1"}}, 1, -1}, error));
  EXPECT_EQ(error, "attribute 'points' needs x, y pairs, got an odd count of 3 numbers");
  EXPECT_EQ(*svgShapePathData(XmlElement{"line", {{"x2", "3"}, {"y2", "4"}}, 1, -1}, error), "M 0,0 L 3,4 ");
  EXPECT_EQ(*svgShapePathData(XmlElement{"rect", {{"width", "0"}, {"height", "4"}}, 1, -1}, error), "")
      << "a rect of zero width is not drawn";
}

TEST(SimWorldSvgDocument, UserSpaceComposesDownTheTree)
{
  const auto parsed = SvgDocument::parse(
      "<svg viewBox=\"0 0 100 100\"><g transform=\"translate(10 20)\"><g transform=\"scale(2)\">"
      "<path id=\"p\" d=\"M 1 1 L 2 1\" transform=\"rotate(90)\"/></g></g><defs><path id=\"hidden\" d=\"M0 "
      "0\"/>"
      "</defs></svg>");
  ASSERT_TRUE(parsed.document) << parsed.error;
  const SvgDocument& document = *parsed.document;
  const auto path = document.findById("p");
  ASSERT_TRUE(path);
  const auto outline = document.outline(*path, 0.01);
  ASSERT_EQ(outline.subpaths.size(), 1u);
  // rotate(90): (1,1) -> (-1,1); scale(2): (-2,2); translate: (8,22).
  EXPECT_NEAR((outline.subpaths[0].points[0] - Point(8, 22)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((outline.subpaths[0].points[1] - Point(8, 24)).norm(), 0.0, 1e-12);
  EXPECT_TRUE(document.isDrawn(*path));
  EXPECT_FALSE(document.isDrawn(*document.findById("hidden")));
  EXPECT_EQ(document.describe(*path), "element <path> 'p' (line 1)");
  const auto bad = SvgDocument::parse(
      "<svg viewBox=\"0 0 1 1\">\n<g id=\"layer\" transform=\"scale(\">\n<path id=\"q\" d=\"M0 "
      "0\"/></g></svg>");
  ASSERT_TRUE(bad.document);
  EXPECT_EQ(
      bad.document->outline(2, 0.01).error,
      "transform of element <g> 'layer' (line 2): at character 6: 'scale(' needs numbers and a closing ')'");
}

}  // namespace
}  // namespace ifar::sim
