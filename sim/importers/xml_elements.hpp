#pragma once
// A small reader for the start tags of an XML document: element name, attributes and line. Enough for
// SVG scenario files, whose content is in attributes; text content, namespaces and entities beyond the
// five predefined ones are not interpreted.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace ifar::sim {

struct XmlElement {
  std::string name;                               // as written, e.g. "svg:path"
  std::map<std::string, std::string> attributes;  // entity references decoded
  int line = 0;                                   // 1-based line of the '<'

  /// Name without namespace prefix: "path" for "svg:path".
  std::string localName() const;
  std::optional<std::string> attribute(const std::string& key) const;
};

struct XmlScan {
  std::vector<XmlElement> elements;  // start and empty-element tags in document order
  std::string error;                 // "line N: problem" when the markup is malformed; elements then partial
};

XmlScan scanXmlElements(const std::string& text);

}  // namespace ifar::sim
