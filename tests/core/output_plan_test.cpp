// The output planner (core/output_plan.h): aliasing by device and inode, non-regular targets, empty
// names, depfile paths, and temporary names that stay within 255 bytes.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>

#include "bake/core/atomic_file.h"
#include "core/output_plan.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

void touch(const fs::path& path) { ASSERT_TRUE(writeFileAtomic(path, std::string("x")).isOk()); }

TEST(OutputPlan, OutputThatIsAnInputIsRefusedWhateverItsSpelling) {
  const fs::path dir = test::freshTempDir("plan_alias");
  touch(dir / "in.glb");
  fs::create_directory(dir / "sub");
  fs::create_hard_link(dir / "in.glb", dir / "hard.glb");
  fs::create_symlink(dir / "in.glb", dir / "soft.glb");
  const std::string input = (dir / "in.glb").string();
  for (const fs::path& output : {dir / "in.glb", dir / "sub" / ".." / "in.glb", dir / "hard.glb", dir / "soft.glb"}) {
    const Status status = checkDistinctFiles({input}, {output});
    EXPECT_EQ(status.code(), ExitCode::Usage) << output;
    EXPECT_NE(status.message().find("also an input"), std::string::npos) << status.message();
  }
  EXPECT_TRUE(checkDistinctFiles({input}, {dir / "out.glb"}).isOk());
}

TEST(OutputPlan, TwoOutputsNamingOneFileAreRefused) {
  const fs::path dir = test::freshTempDir("plan_twice");
  EXPECT_EQ(checkDistinctFiles({}, {dir / "o.glb", dir / "." / "o.glb"}).code(), ExitCode::Usage);
  CommonOptions common;
  common.reportPath = (dir / "o.glb").string();
  const Status status = planOutputs({{}, {(dir / "o.glb").string()}}, common);
  EXPECT_EQ(status.code(), ExitCode::Usage);
  EXPECT_NE(status.message().find("named twice"), std::string::npos) << status.message();
  forgetOutputPlan();
}

TEST(OutputPlan, DeviceNodesAndFifosAreNeverReplaced) {
  const fs::path dir = test::freshTempDir("plan_devices");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  for (const fs::path& target : {fs::path("/dev/null"), fs::path("/dev/full"), dir / "fifo", dir}) {
    const Status status = checkReplaceable(target);
    EXPECT_EQ(status.code(), ExitCode::Io) << target;
    // The single writer refuses too, whatever called it.
    EXPECT_EQ(writeFileAtomic(target, std::string("data")).code(), ExitCode::Io) << target;
  }
  struct stat info {};
  ASSERT_EQ(::stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
  ASSERT_EQ(::stat((dir / "fifo").c_str(), &info), 0);
  EXPECT_TRUE(S_ISFIFO(info.st_mode));
}

TEST(OutputPlan, EmptyNamesMissingFoldersAndDepfilePathsFailBeforeWork) {
  const fs::path dir = test::freshTempDir("plan_checks");
  CommonOptions common;
  EXPECT_EQ(planOutputs({{}, {""}}, common).code(), ExitCode::Usage);
  EXPECT_EQ(planOutputs({{}, {(dir / "missing" / "o.glb").string()}}, common).code(), ExitCode::Io);
  common.depfilePath = (dir / "o.d").string();
  EXPECT_EQ(planOutputs({{(dir / "a;b.obj").string()}, {(dir / "o.glb").string()}}, common).code(), ExitCode::Usage);
  EXPECT_TRUE(planOutputs({{(dir / "a:b.obj").string()}, {(dir / "o.glb").string()}}, common).isOk());
  EXPECT_TRUE(outputsPlanned());
  EXPECT_TRUE(isPlannedOutput(dir / "o.glb"));
  EXPECT_TRUE(isPlannedOutput(dir / "." / "o.d"));
  EXPECT_FALSE(isPlannedOutput(dir / "other.glb"));
  forgetOutputPlan();
  EXPECT_FALSE(outputsPlanned());
  EXPECT_TRUE(fs::is_empty(dir)) << "planning leaves nothing behind";
}

TEST(OutputPlan, TemporaryNamesStayWithinTheNameLimit) {
  const fs::path dir = test::freshTempDir("plan_long_name");
  const std::string longName = std::string(246, 'n') + ".glb";  // 250 bytes: a legal name
  const std::string pattern = temporaryPatternFor(dir / longName, ".png");
  EXPECT_LE(fs::path(pattern).filename().string().size(), 255u);
  ASSERT_TRUE(writeFileAtomic(dir / longName, std::string("data")).isOk());
  EXPECT_TRUE(fs::exists(dir / longName));
}

}  // namespace
}  // namespace bake
