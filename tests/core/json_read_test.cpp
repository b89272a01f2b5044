// Strict JSON reading (core/json_read.h): the nesting limit, strings that hold brackets, the BOM.
#include <gtest/gtest.h>

#include "core/json_read.h"

namespace bake {
namespace {

TEST(JsonRead, DeepNestingIsRefusedBeforeParsing) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const Result<nlohmann::json> parsed = parseJsonText(deep, "deep.json");
  ASSERT_FALSE(parsed.isOk());
  EXPECT_EQ(parsed.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(parsed.status().message().find("nested deeper than"), std::string::npos);
  EXPECT_EQ(parsed.status().where().element, "byte " + std::to_string(kMaxJsonDepth));
}

TEST(JsonRead, TheLimitItselfIsAllowedAndBracketsInStringsDoNotCount) {
  const std::string atLimit = std::string(kMaxJsonDepth, '[') + std::string(kMaxJsonDepth, ']');
  EXPECT_TRUE(parseJsonText(atLimit, "a.json").isOk());
  const std::string quoted = "{\"k\": \"" + std::string(1000, '[') + "\\\"[{\"}";
  EXPECT_TRUE(parseJsonText(quoted, "q.json").isOk());
}

TEST(JsonRead, ByteOrderMarkAndSyntaxErrors) {
  const Result<nlohmann::json> bom = parseJsonText("\xEF\xBB\xBF{\"a\": 1}", "bom.json");
  ASSERT_TRUE(bom.isOk());
  EXPECT_EQ((*bom)["a"], 1);
  const Result<nlohmann::json> broken = parseJsonText("{\"a\": }", "broken.json");
  ASSERT_FALSE(broken.isOk());
  EXPECT_EQ(broken.status().where().file, "broken.json");
  EXPECT_EQ(broken.status().where().element.rfind("byte ", 0), 0u);
}

}  // namespace
}  // namespace bake
