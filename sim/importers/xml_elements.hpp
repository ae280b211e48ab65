#pragma once
// The elements of an XML document as the SVG importers read them: name, attributes, line and enclosing
// element, in document order. tinyxml2 parses (well-formedness, entities, comments, CDATA); this keeps the
// project's bound on nesting and states its errors as one line ("line 3: element <path>: ...").

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ifar::sim {

struct XmlElement {
  std::string name;                               // as written, e.g. "svg:path"
  std::map<std::string, std::string> attributes;  // entity references decoded
  int line = 0;                                   // 1-based line of the '<'
  int parent = -1;  // index in XmlScan::elements of the enclosing element; -1 at the top

  /// Name without namespace prefix: "path" for "svg:path".
  std::string localName() const;
  std::optional<std::string> attribute(const std::string& key) const;
};

/// Elements nested deeper than this are refused (a bound for any input; SVG drawings nest a few levels).
constexpr int kXmlMaxDepth = 256;

struct XmlScan {
  std::vector<XmlElement> elements;  // start and empty-element tags in document order
  std::string error;                 // "line N: problem" when the markup is malformed; elements then empty
};

XmlScan scanXmlElements(const std::string& text);

}  // namespace ifar::sim
