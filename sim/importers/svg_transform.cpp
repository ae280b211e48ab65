#include "sim/importers/svg_transform.hpp"

#include <cctype>
#include <cmath>
#include <vector>

#include <Eigen/SVD>

#include "sim/importers/svg_number.hpp"

namespace ifar::sim {
namespace {

constexpr double kPi = 3.14159265358979323846;

double radians(double degrees)
{
  return std::fmod(degrees, 360.0) * kPi / 180.0;
}

/// The transform named `name` with `values`, or an empty optional when the count does not fit it.
std::optional<SvgTransform> makeTransform(const std::string& name, const std::vector<double>& values)
{
  const std::size_t count = values.size();
  SvgTransform transform = SvgTransform::Identity();
  if (name == "matrix" && count == 6) {
    transform.matrix() << values[0], values[2], values[4], values[1], values[3], values[5], 0.0, 0.0, 1.0;
  } else if (name == "translate" && (count == 1 || count == 2)) {
    transform.translation() = geometry::Point(values[0], count == 2 ? values[1] : 0.0);
  } else if (name == "scale" && (count == 1 || count == 2)) {
    transform.linear() = Eigen::Vector2d(values[0], count == 2 ? values[1] : values[0]).asDiagonal();
  } else if (name == "rotate" && (count == 1 || count == 3)) {
    const geometry::Point pivot = count == 3 ? geometry::Point(values[1], values[2]) : geometry::Point(0, 0);
    transform =
        Eigen::Translation2d(pivot) * Eigen::Rotation2Dd(radians(values[0])) * Eigen::Translation2d(-pivot);
  } else if (name == "skewX" && count == 1) {
    transform.linear()(0, 1) = std::tan(radians(values[0]));
  } else if (name == "skewY" && count == 1) {
    transform.linear()(1, 0) = std::tan(radians(values[0]));
  } else {
    return std::nullopt;
  }
  return transform;
}

}  // namespace

SvgTransformParse parseSvgTransform(const std::string& text)
{
  SvgTransformParse result;
  std::size_t position = 0;
  const auto fail = [&result, &position](const std::string& problem) {
    result.transform = SvgTransform::Identity();
    result.error = "at character " + std::to_string(position) + ": " + problem;
    return result;
  };
  while (true) {
    skipSvgSeparators(text, position);
    if (position >= text.size()) {
      return result;
    }
    const std::size_t name_begin = position;
    while (position < text.size() && std::isalpha(static_cast<unsigned char>(text[position])) != 0) {
      ++position;
    }
    const std::string name = text.substr(name_begin, position - name_begin);
    if (name.empty()) {
      return fail("expected a transform name (matrix, translate, scale, rotate, skewX, skewY)");
    }
    while (position < text.size() && std::isspace(static_cast<unsigned char>(text[position])) != 0) {
      ++position;
    }
    if (position >= text.size() || text[position] != '(') {
      return fail("expected '(' after '" + name + "'");
    }
    ++position;
    std::vector<double> values;
    while (true) {
      skipSvgSeparators(text, position);
      if (position < text.size() && text[position] == ')') {
        ++position;
        break;
      }
      double value = 0.0;
      if (values.size() >= 6 || !readSvgNumber(text, position, value)) {
        return fail("'" + name + "(' needs numbers and a closing ')'");
      }
      values.push_back(value);
    }
    const auto transform = makeTransform(name, values);
    if (!transform) {
      position = name_begin;
      return fail("'" + name + "' with " + std::to_string(values.size()) +
                  " numbers is not an SVG transform (matrix 6, translate 1-2, scale 1-2, rotate 1 or 3, "
                  "skewX/skewY 1)");
    }
    result.transform = result.transform * *transform;
  }
}

double largestStretch(const SvgTransform& transform)
{
  const Eigen::JacobiSVD<Eigen::Matrix2d> decomposition(transform.linear());
  return decomposition.singularValues()(0);
}

}  // namespace ifar::sim
