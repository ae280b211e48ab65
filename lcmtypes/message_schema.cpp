#include "lcmtypes/message_schema.hpp"

#include <string>

namespace ifar::lcmtypes {

const lcm_wire::Schema& messageSchema()
{
  static const lcm_wire::Schema schema = [] {
    std::vector<std::string_view> texts;
    std::vector<std::string> names;
    for (const LcmDefinition& definition : lcmDefinitions()) {
      texts.push_back(definition.text);
      names.emplace_back(definition.file_name);
    }
    return lcm_wire::Schema::parse(texts, names);
  }();
  return schema;
}

}  // namespace ifar::lcmtypes
