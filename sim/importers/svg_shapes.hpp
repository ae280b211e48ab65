#pragma once
// The outline of one SVG drawing element in its own user units (before any transform): <path> by its path
// data, and the basic shapes <rect> (with rounded corners), <circle>, <ellipse>, <polygon>, <polyline> and
// <line> as SVG 1.1 chapter 9 defines them through equivalent path data.

#include <optional>
#include <string>

#include "sim/importers/svg_path.hpp"
#include "sim/importers/xml_elements.hpp"

namespace ifar::sim {

/// A length attribute: a number, optionally followed by "px" (a user unit); `fallback` when absent; nullopt
/// with `error` set for anything else ("attribute 'r' is not a length in user units: '2cm'").
std::optional<double> svgLengthAttribute(const XmlElement& element, const std::string& key, double fallback,
                                         std::string& error);

/// True for the element names (without namespace prefix) svgShapeOutline reads.
bool isSvgShapeElement(const std::string& local_name);

/// The element's subpaths, flattened with `flattening` (in the element's units); `error` says what is wrong
/// with its attributes or path data ("attribute 'r' is not a length: 'big'", "path data at character 9:
/// ..."). A shape of zero size (an SVG renderer draws nothing) has no subpaths and no error.
SvgPathParse svgShapeOutline(const XmlElement& element, const SvgFlattening& flattening);

/// The path data equivalent to a basic shape, or nullopt with `error` set. Exposed for tests.
std::optional<std::string> svgShapePathData(const XmlElement& element, std::string& error);

}  // namespace ifar::sim
