#include "common/json_text.hpp"

#include <string>

#include <gtest/gtest.h>

namespace ifar::common {
namespace {

TEST(JsonString, QuotesPlainText)
{
  EXPECT_EQ(jsonString("arrived"), "\"arrived\"");
  EXPECT_EQ(jsonString(""), "\"\"");
}

TEST(JsonString, EscapesWhatJsonRequires)
{
  EXPECT_EQ(jsonString("box \"1\" at C:\\logs"), "\"box \\\"1\\\" at C:\\\\logs\"");
  EXPECT_EQ(jsonString("line\nnext\ttab\rreturn"), "\"line\\nnext\\ttab\\rreturn\"");
  EXPECT_EQ(jsonString(std::string("bell\x07zero") + '\0' + "end"), "\"bell\\u0007zero\\u0000end\"");
}

TEST(JsonString, KeepsUtf8Bytes)
{
  EXPECT_EQ(jsonString("60 m \xC3\x97 60 m"), "\"60 m \xC3\x97 60 m\"");
}

}  // namespace
}  // namespace ifar::common
