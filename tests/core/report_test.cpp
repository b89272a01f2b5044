#include <gtest/gtest.h>

#include "bake/core/atomic_file.h"
#include "bake/core/report.h"
#include "core/hash.h"
#include "core/progress.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

TEST(Hash, KnownValueAndFileMatchesBytes) {
  const std::string text = "bake";
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
  const std::string h = hashBytes(bytes);
  EXPECT_EQ(h.rfind("xxh3-128:", 0), 0u);
  EXPECT_EQ(h.size(), 9u + 32u);
  const fs::path dir = test::freshTempDir("hash");
  ASSERT_TRUE(writeFileAtomic(dir / "f", text).isOk());
  auto fileHash = hashFile(dir / "f");
  ASSERT_TRUE(fileHash.isOk());
  EXPECT_EQ(*fileHash, h);
  EXPECT_NE(hashBytes({}), h);
}

TEST(Report, RecordsInputsStagesAccuracyAndWarnings) {
  const fs::path dir = test::freshTempDir("report");
  ASSERT_TRUE(writeFileAtomic(dir / "in.txt", std::string("12345")).isOk());
  Report report("testtool", "0.0.1");
  ASSERT_TRUE(report.addInput(dir / "in.txt").isOk());
  EXPECT_EQ(report.addInput(dir / "missing").code(), ExitCode::Io);
  report.addStage("load", 0.25);
  report.addStage("solve", 0.5);
  report.addAccuracy("geodesic distance", "exact window propagation", {{"meanRelative", 0.01}});
  Diagnostics diagnostics("testtool", true);
  diagnostics.warning("welded", "welded 4 vertices");
  report.takeWarnings(diagnostics);
  const nlohmann::json json = report.toJson();
  EXPECT_EQ(json["inputs"][0]["bytes"], 5);
  EXPECT_DOUBLE_EQ(json["totalSeconds"].get<double>(), 0.75);
  EXPECT_EQ(json["accuracy"][0]["reference"], "exact window propagation");
  EXPECT_EQ(json["warnings"][0]["count"], 1);
  EXPECT_EQ(json["status"]["exitCode"], 0);
}

TEST(Progress, RendersABar) {
  EXPECT_EQ(Progress::render("solve", 5, 10, 10), "solve [#####     ] 50%");
  EXPECT_EQ(Progress::render("solve", 0, 0, 4), "solve [####] 100%");
  // The time left, from the rate so far; nothing while too early to tell or when done.
  EXPECT_EQ(Progress::remaining(1.0, 5, 10), "");
  EXPECT_EQ(Progress::remaining(10.0, 0, 10), "");
  EXPECT_EQ(Progress::remaining(10.0, 50, 100), ", about 10 s left");
  EXPECT_EQ(Progress::remaining(60.0, 10, 100), ", about 9 min 0 s left");
  EXPECT_EQ(Progress::remaining(3600.0, 25, 100), ", about 3 h 0 min left");
  EXPECT_EQ(Progress::remaining(10.0, 100, 100), "");
  char drawn[128] = {};
  std::FILE* stream = ::fmemopen(drawn, sizeof drawn, "w");
  {
    Progress progress("x", 4, true, stream);
    progress.update(4);
  }
  std::fclose(stream);
  EXPECT_STREQ(drawn, "\rx [##############################] 100%\033[K\n");  // \033[K: clear the rest of the line
  char silent[64] = {};
  stream = ::fmemopen(silent, sizeof silent, "w");
  {
    Progress progress("x", 4, false, stream);
    progress.update(2);
  }
  std::fclose(stream);
  EXPECT_STREQ(silent, "") << "a disabled bar (not a terminal, or --quiet) draws nothing";
}

}  // namespace
}  // namespace bake
