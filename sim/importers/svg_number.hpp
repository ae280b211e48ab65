#pragma once
// Numbers as SVG writes them in path data, point lists, transforms and viewBox: an optional sign, digits
// with an optional fraction, an optional exponent; separated by white space and/or one comma, or by
// nothing where the next number cannot continue the previous one ("1.5.5" is 1.5 then .5, "1-2" is 1
// then -2).

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace ifar::sim {

/// Moves `position` past white space and commas.
void skipSvgSeparators(const std::string& text, std::size_t& position);

/// Reads one number at `position` (after separators) and moves past it; false, with `position` only past
/// the separators, when there is no number there or it is out of the range of a double.
bool readSvgNumber(const std::string& text, std::size_t& position, double& value);

/// Every number of `text`, or nullopt when anything else is in it.
std::optional<std::vector<double>> parseSvgNumberList(const std::string& text);

}  // namespace ifar::sim
