#include "tools/echo/json_schema.hpp"

#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "lcmtypes/message_schema.hpp"

namespace ifar::echo {
namespace {

TEST(JsonSchema, EveryProjectTypeHasAnObjectSchemaNamingEachMember)
{
  const lcm_wire::Schema& schema = lcmtypes::messageSchema();
  ASSERT_FALSE(schema.types().empty());
  for (const lcm_wire::StructType& type : schema.types()) {
    const std::string text = jsonSchemaOf(schema, type);
    const YAML::Node root = YAML::Load(text);
    EXPECT_EQ(root["$schema"].as<std::string>(), "https://json-schema.org/draft/2020-12/schema") << type.name;
    EXPECT_EQ(root["type"].as<std::string>(), "object") << type.name;
    EXPECT_EQ(root["title"].as<std::string>(), type.name);
    ASSERT_EQ(root["properties"].size(), type.fields.size()) << text;
    for (const lcm_wire::Field& field : type.fields) {
      EXPECT_TRUE(root["properties"][field.name]["type"].IsScalar()) << type.name << "." << field.name;
    }
  }
}

TEST(JsonSchema, ArraysNestedStructsAndBytesAreShapedAsEchoPrintsThem)
{
  const lcm_wire::Schema& schema = lcmtypes::messageSchema();
  const YAML::Node pose = YAML::Load(jsonSchemaOf(schema, *schema.find("pose_t")));
  EXPECT_EQ(pose["properties"]["orientation"]["type"].as<std::string>(), "array");
  EXPECT_EQ(pose["properties"]["orientation"]["minItems"].as<int>(), 4);
  EXPECT_EQ(pose["properties"]["orientation"]["items"]["type"].as<std::string>(), "number");
  // A byte array is one string of hex digits; its length is a member before it.
  const YAML::Node packet = YAML::Load(jsonSchemaOf(schema, *schema.find("velodyne_packet_t")));
  EXPECT_EQ(packet["properties"]["data"]["type"].as<std::string>(), "string");
  EXPECT_FALSE(packet["properties"]["data"]["minLength"]);
  // Variable arrays of structs: items are the struct's object schema, inline.
  const YAML::Node graph = YAML::Load(jsonSchemaOf(schema, *schema.find("dv_graph_t")));
  const YAML::Node vertices = graph["properties"]["vertices"];
  EXPECT_EQ(vertices["type"].as<std::string>(), "array");
  EXPECT_FALSE(vertices["minItems"]);
  EXPECT_EQ(vertices["items"]["type"].as<std::string>(), "object");
  EXPECT_EQ(vertices["items"]["title"].as<std::string>(), "graph_vertex_t");
  EXPECT_FALSE(vertices["items"]["$schema"]);  // the dialect at the root only
}

}  // namespace
}  // namespace ifar::echo
