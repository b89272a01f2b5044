#include <gtest/gtest.h>

#include "bake/core/diagnostics.h"
#include "bake/core/status.h"

namespace bake {
namespace {

Result<int> parsePositive(int value) {
  if (value <= 0) return invalidInput("not positive", {"in.txt", "line 3"});
  return value;
}

Status doubleIt(int value, int& out) {
  BAKE_ASSIGN_OR_RETURN(const int parsed, parsePositive(value));
  out = 2 * parsed;
  return {};
}

TEST(Status, ExitCodesAreTheDocumentedNumbers) {
  EXPECT_EQ(int(ExitCode::Ok), 0);
  EXPECT_EQ(int(ExitCode::Usage), 1);
  EXPECT_EQ(int(ExitCode::Io), 2);
  EXPECT_EQ(int(ExitCode::InvalidInput), 3);
  EXPECT_EQ(int(ExitCode::Internal), 4);
  EXPECT_EQ(int(ExitCode::Unsupported), 5);
}

TEST(Status, DescribeNamesFileAndElement) {
  const Status status = invalidInput("index 9 out of range", {"mesh.obj", "line 12"});
  EXPECT_EQ(status.describe(), "mesh.obj: line 12: index 9 out of range");
  EXPECT_EQ(formatError("geobake", status), "geobake: error: mesh.obj: line 12: index 9 out of range");
  Status partial = ioError("cannot open");
  partial.inFile("a.glb").inFile("ignored.glb");
  EXPECT_EQ(partial.describe(), "a.glb: cannot open");
}

TEST(Status, ResultPropagatesThroughMacros) {
  int out = 0;
  EXPECT_TRUE(doubleIt(4, out).isOk());
  EXPECT_EQ(out, 8);
  const Status failed = doubleIt(-1, out);
  EXPECT_EQ(failed.code(), ExitCode::InvalidInput);
  EXPECT_EQ(failed.where().element, "line 3");
}

TEST(Diagnostics, FormatsLinesAndCountsWarnings) {
  char buffer[512] = {};
  std::FILE* stream = ::fmemopen(buffer, sizeof buffer, "w");
  Diagnostics diagnostics("tambake", false, stream);
  diagnostics.warning("welded", "welded 3 vertices");
  diagnostics.warning("welded", "welded 2 vertices");
  diagnostics.error(invalidInput("bad tone", {"style.json", "tones[2]"}));
  std::fclose(stream);
  EXPECT_STREQ(buffer,
               "tambake: warning: welded 3 vertices\n"
               "tambake: warning: welded 2 vertices\n"
               "tambake: error: style.json: tones[2]: bad tone\n");
  ASSERT_EQ(diagnostics.warnings().count("welded"), 1u);
  EXPECT_EQ(diagnostics.warnings().at("welded").count, 2);
  EXPECT_EQ(diagnostics.warnings().at("welded").message, "welded 3 vertices");
}

TEST(Diagnostics, QuietKeepsErrorsOnly) {
  char buffer[256] = {};
  std::FILE* stream = ::fmemopen(buffer, sizeof buffer, "w");
  Diagnostics diagnostics("bakeinfo", true, stream);
  diagnostics.warning("w", "hidden");
  diagnostics.info("hidden too");
  diagnostics.error("shown");
  std::fclose(stream);
  EXPECT_STREQ(buffer, "bakeinfo: error: shown\n");
  EXPECT_EQ(diagnostics.warnings().at("w").count, 1);  // still counted for the report
}

}  // namespace
}  // namespace bake
