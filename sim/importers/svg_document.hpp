#pragma once
// An SVG file as the importers read it: its elements in document order with their enclosing elements, the
// user space each is drawn in (its own and its ancestors' `transform` attributes composed down from the
// root), lookup by id, the root's viewBox, and the outline of any drawing element flattened and mapped into
// the root's user units (y down, as in the file).

#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "sim/importers/svg_path.hpp"
#include "sim/importers/svg_transform.hpp"
#include "sim/importers/xml_elements.hpp"

namespace ifar::sim {

struct SvgViewBox {
  double min_x = 0.0;
  double min_y = 0.0;
  double width = 0.0;
  double height = 0.0;
  double largerSide() const { return width > height ? width : height; }
};

/// Four numbers with positive width and height, or nullopt.
std::optional<SvgViewBox> parseSvgViewBox(const std::string& text);

class SvgDocument {
 public:
  struct Parse;
  /// The error reads "malformed XML at line N: ..." or names the element: "element <svg> (line 1): ...".
  static Parse parse(const std::string& text);

  const std::vector<XmlElement>& elements() const { return elements_; }
  const XmlElement& element(std::size_t index) const { return elements_[index]; }
  const SvgViewBox& viewBox() const { return view_box_; }

  /// The first element with this id.
  std::optional<std::size_t> findById(const std::string& id) const;
  /// True when `ancestor` encloses `index` (directly or further up).
  bool isInside(std::size_t index, std::size_t ancestor) const;
  /// False for elements SVG does not draw where they stand: in <defs>, <metadata>, <clipPath>, <mask>,
  /// <symbol>, <pattern>, <marker>, and in the other programs' elements (namo_config, Inkscape's namedview).
  bool isDrawn(std::size_t index) const { return drawn_[index]; }

  /// "element <path> 'wall_1' (line 12)".
  std::string describe(std::size_t index) const;

  /// The element's outline in root user units: its subpaths flattened so that curves stay within
  /// `tolerance` root units of their pieces, then mapped through its user space. `error` names the problem
  /// without the element ("path data at character 9: ...", "transform: at character 3: ...", or for an
  /// ancestor's "transform of element <g> 'layer' (line 4): ...").
  SvgPathParse outline(std::size_t index, double tolerance) const;

  /// Element index to root user units (identity for an element with a bad transform; see outline()).
  const SvgTransform& userSpace(std::size_t index) const { return user_space_[index]; }

 private:
  std::vector<XmlElement> elements_;
  SvgViewBox view_box_;
  std::vector<SvgTransform, Eigen::aligned_allocator<SvgTransform>> user_space_;
  struct BadTransform {
    int element = -1;  // the element (itself or an ancestor) whose transform attribute is malformed
    std::string problem;
  };
  std::vector<BadTransform> bad_transforms_;  // per element
  std::vector<bool> drawn_;
  std::unordered_map<std::string, std::size_t> ids_;
};

struct SvgDocument::Parse {
  std::optional<SvgDocument> document;
  std::string error;
};

}  // namespace ifar::sim
