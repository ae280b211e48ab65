#include "sim/importers/svg_path.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>

#include "sim/importers/svg_arc.hpp"
#include "sim/importers/svg_number.hpp"

namespace ifar::sim {
namespace {

using geometry::Point;

constexpr double kPi = 3.14159265358979323846;

bool isCommand(char character)
{
  return character != '\0' && std::strchr("MmLlHhVvZzCcSsQqTtAa", character) != nullptr;
}

/// A piece count as an int within 1..kSvgCurveMaxPieces (non-finite counts, from huge coordinates or a
/// zero-size curve, stay in range too).
int boundedPieces(double pieces)
{
  if (!(pieces >= 1.0)) {
    return 1;
  }
  return pieces >= kSvgCurveMaxPieces ? kSvgCurveMaxPieces : static_cast<int>(std::ceil(pieces));
}

/// Pieces of a Bezier curve of `degree` with control points `points` so that the uniform-parameter
/// polyline stays within `tolerance` of it (Wang's bound: sqrt(d (d - 1) / 8 x max second difference / tol)).
int bezierPieces(const Point* points, int degree, const SvgFlattening& flattening)
{
  if (!(flattening.tolerance > 0.0)) {
    return flattening.curve_segments;
  }
  double largest_second_difference = 0.0;
  for (int index = 0; index + 2 <= degree; ++index) {
    largest_second_difference = std::max(
        largest_second_difference, (points[index] - 2.0 * points[index + 1] + points[index + 2]).norm());
  }
  return boundedPieces(
      std::sqrt(degree * (degree - 1) / 8.0 * largest_second_difference / flattening.tolerance));
}

/// Pieces of an arc: equal parameter steps whose chords stay within the tolerance of the larger circle
/// (an ellipse's deviation from a chord is at most its larger radius times the unit circle's).
int arcPieces(const SvgArcCentre& arc, const SvgFlattening& flattening)
{
  const double turn = std::abs(arc.sweep_angle);
  if (!(flattening.tolerance > 0.0)) {
    return boundedPieces(flattening.curve_segments * std::ceil(turn / (0.5 * kPi) - 1e-9));
  }
  const double radius = std::max(arc.radius_x, arc.radius_y);
  const double step =
      std::min(0.5 * kPi, 2.0 * std::acos(1.0 - std::min(1.0, flattening.tolerance / radius)));
  return boundedPieces(turn / step);
}

class PathParser {
 public:
  PathParser(const std::string& data, const SvgFlattening& flattening) : data_(data), flattening_(flattening)
  {
  }

  SvgPathParse run()
  {
    SvgPathParse result;
    char command = '\0';
    while (true) {
      skipSeparators();
      if (position_ >= data_.size()) {
        break;
      }
      const char next = data_[position_];
      if (std::isalpha(static_cast<unsigned char>(next)) != 0) {
        if (!isCommand(next)) {
          return fail(result, "unknown path command '" + std::string(1, next) + "'");
        }
        command = next;
        ++position_;
        if (command == 'Z' || command == 'z') {
          closeSubpath(result);
          continue;
        }
      } else if (command == '\0') {
        return fail(result, "path data must start with a moveto command");
      } else if (command == 'Z' || command == 'z') {
        return fail(result, "number after closepath without a command");
      }
      if (!execute(command, result)) {
        return result;
      }
      if (points_ > kSvgPathMaxPoints) {
        return fail(result, "more than " + std::to_string(kSvgPathMaxPoints) +
                                " points after flattening the curves (tolerance too fine for the drawing)");
      }
      // After a moveto, further coordinate pairs are implicit linetos.
      if (command == 'M') {
        command = 'L';
      } else if (command == 'm') {
        command = 'l';
      }
    }
    finishSubpath(result);
    return result;
  }

 private:
  SvgPathParse& fail(SvgPathParse& result, const std::string& problem) const
  {
    result.subpaths.clear();
    result.error = "at character " + std::to_string(position_) + ": " + problem;
    return result;
  }

  void skipSeparators() { skipSvgSeparators(data_, position_); }

  bool readNumber(double& value) { return readSvgNumber(data_, position_, value); }

  /// An arc flag: a single '0' or '1', which may run straight into the next number ("011").
  bool readFlag(bool& flag)
  {
    skipSeparators();
    if (position_ >= data_.size() || (data_[position_] != '0' && data_[position_] != '1')) {
      return false;
    }
    flag = data_[position_] == '1';
    ++position_;
    return true;
  }

  bool readNumbers(double* values, int count, SvgPathParse& result, char command)
  {
    for (int index = 0; index < count; ++index) {
      if (!readNumber(values[index])) {
        fail(result, std::string("command '") + command + "' expects " + std::to_string(count) + " numbers");
        return false;
      }
    }
    return true;
  }

  void finishSubpath(SvgPathParse& result)
  {
    if (!current_.points.empty()) {
      result.subpaths.push_back(std::move(current_));
    }
    current_ = SvgSubpath();
  }

  void closeSubpath(SvgPathParse& result)
  {
    if (!current_.points.empty()) {
      current_.closed = true;
      pen_ = subpath_start_;
    }
    finishSubpath(result);
    last_control_valid_ = false;
  }

  void lineTo(const Point& point)
  {
    if (current_.points.empty()) {
      current_.points.push_back(pen_);  // drawing after Z continues from the subpath's start
      ++points_;
    }
    current_.points.push_back(point);
    ++points_;
    pen_ = point;
  }

  void cubic(const Point& first, const Point& second, const Point& end)
  {
    const Point controls[4] = {pen_, first, second, end};
    const int pieces = bezierPieces(controls, 3, flattening_);
    for (int step = 1; step <= pieces; ++step) {
      const double t = static_cast<double>(step) / pieces;
      const double u = 1.0 - t;
      lineTo(step == pieces ? end
                            : Point(u * u * u * controls[0] + 3.0 * u * u * t * first +
                                    3.0 * u * t * t * second + t * t * t * end));
    }
    last_control_ = second;
    last_control_valid_ = true;
    last_was_cubic_ = true;
  }

  void quadratic(const Point& control, const Point& end)
  {
    const Point controls[3] = {pen_, control, end};
    const int pieces = bezierPieces(controls, 2, flattening_);
    for (int step = 1; step <= pieces; ++step) {
      const double t = static_cast<double>(step) / pieces;
      const double u = 1.0 - t;
      lineTo(step == pieces ? end : Point(u * u * controls[0] + 2.0 * u * t * control + t * t * end));
    }
    last_control_ = control;
    last_control_valid_ = true;
    last_was_cubic_ = false;
  }

  /// SVG F.6.2: an arc to the current point is drawn as nothing, one with a zero radius as a line.
  void arc(double radius_x, double radius_y, double rotation_deg, bool large_arc, bool sweep,
           const Point& end)
  {
    if (end == pen_) {
      return;
    }
    if (radius_x == 0.0 || radius_y == 0.0) {
      lineTo(end);
      return;
    }
    const SvgArcCentre centre = svgArcCentre(pen_, radius_x, radius_y, rotation_deg, large_arc, sweep, end);
    const int pieces = arcPieces(centre, flattening_);
    for (int step = 1; step <= pieces; ++step) {
      lineTo(step == pieces ? end : centre.pointAt(centre.start_angle + centre.sweep_angle * step / pieces));
    }
  }

  /// The reflection of the previous curve's control point, or the pen when the previous command differs.
  Point reflected(bool want_cubic) const
  {
    if (last_control_valid_ && last_was_cubic_ == want_cubic) {
      return 2.0 * pen_ - last_control_;
    }
    return pen_;
  }

  bool readArc(SvgPathParse& result, char command, const Point& origin)
  {
    double radii_and_rotation[3];
    bool large_arc = false;
    bool sweep = false;
    double end[2];
    if (!readNumbers(radii_and_rotation, 3, result, command)) {
      return false;
    }
    if (!readFlag(large_arc) || !readFlag(sweep)) {
      fail(result,
           std::string("command '") + command + "' expects flags 0 or 1 after the radii and rotation");
      return false;
    }
    if (!readNumbers(end, 2, result, command)) {
      return false;
    }
    arc(radii_and_rotation[0], radii_and_rotation[1], radii_and_rotation[2], large_arc, sweep,
        origin + Point(end[0], end[1]));
    return true;
  }

  bool execute(char command, SvgPathParse& result)
  {
    const bool relative = std::islower(static_cast<unsigned char>(command)) != 0;
    const Point origin = relative ? pen_ : Point(0.0, 0.0);
    double values[6];
    bool curve = false;
    switch (std::toupper(static_cast<unsigned char>(command))) {
      case 'M': {
        if (!readNumbers(values, 2, result, command)) {
          return false;
        }
        finishSubpath(result);
        pen_ = origin + Point(values[0], values[1]);
        subpath_start_ = pen_;
        current_.points.push_back(pen_);
        ++points_;
        break;
      }
      case 'L': {
        if (!readNumbers(values, 2, result, command)) {
          return false;
        }
        lineTo(origin + Point(values[0], values[1]));
        break;
      }
      case 'H': {
        if (!readNumbers(values, 1, result, command)) {
          return false;
        }
        lineTo(Point(relative ? pen_.x() + values[0] : values[0], pen_.y()));
        break;
      }
      case 'V': {
        if (!readNumbers(values, 1, result, command)) {
          return false;
        }
        lineTo(Point(pen_.x(), relative ? pen_.y() + values[0] : values[0]));
        break;
      }
      case 'C': {
        if (!readNumbers(values, 6, result, command)) {
          return false;
        }
        cubic(origin + Point(values[0], values[1]), origin + Point(values[2], values[3]),
              origin + Point(values[4], values[5]));
        curve = true;
        break;
      }
      case 'S': {
        if (!readNumbers(values, 4, result, command)) {
          return false;
        }
        cubic(reflected(true), origin + Point(values[0], values[1]), origin + Point(values[2], values[3]));
        curve = true;
        break;
      }
      case 'Q': {
        if (!readNumbers(values, 4, result, command)) {
          return false;
        }
        quadratic(origin + Point(values[0], values[1]), origin + Point(values[2], values[3]));
        curve = true;
        break;
      }
      case 'T': {
        if (!readNumbers(values, 2, result, command)) {
          return false;
        }
        quadratic(reflected(false), origin + Point(values[0], values[1]));
        curve = true;
        break;
      }
      case 'A': {
        if (!readArc(result, command, origin)) {
          return false;
        }
        break;
      }
      default:
        fail(result, std::string("unexpected command '") + command + "'");
        return false;
    }
    if (!curve) {
      last_control_valid_ = false;
    }
    return true;
  }

  const std::string& data_;
  const SvgFlattening flattening_;
  std::size_t position_ = 0;
  std::size_t points_ = 0;
  Point pen_ = Point(0.0, 0.0);
  Point subpath_start_ = Point(0.0, 0.0);
  Point last_control_ = Point(0.0, 0.0);
  bool last_control_valid_ = false;
  bool last_was_cubic_ = false;
  SvgSubpath current_;
};

}  // namespace

SvgPathParse parseSvgPath(const std::string& data, const SvgFlattening& flattening)
{
  SvgFlattening checked = flattening;
  checked.curve_segments = std::clamp(checked.curve_segments, 1, kSvgCurveMaxPieces);
  if (!std::isfinite(checked.tolerance) || checked.tolerance < 0.0) {
    checked.tolerance = 0.0;
  }
  return PathParser(data, checked).run();
}

SvgPathParse parseSvgPath(const std::string& data, int curve_segments)
{
  SvgFlattening flattening;
  flattening.curve_segments = curve_segments;
  return parseSvgPath(data, flattening);
}

}  // namespace ifar::sim
