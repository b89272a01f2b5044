#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>

#include "core/atomic_file.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

std::string readText(const fs::path& path) {
  const auto bytes = test::readAll(path);
  return {bytes.begin(), bytes.end()};
}

std::size_t entriesIn(const fs::path& dir) {
  return std::size_t(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

TEST(AtomicFile, WritesAndReplaces) {
  const fs::path dir = test::freshTempDir("atomic_writes");
  const fs::path target = dir / "out.bin";
  ASSERT_TRUE(writeFileAtomic(target, std::string("first")).isOk());
  ASSERT_TRUE(writeFileAtomic(target, std::string("second")).isOk());
  EXPECT_EQ(readText(target), "second");
  EXPECT_EQ(entriesIn(dir), 1u) << "no temporary file may remain";
}

TEST(AtomicFile, FailedWriteLeavesEarlierOutputUntouched) {
  const fs::path dir = test::freshTempDir("atomic_failure");
  const fs::path target = dir / "out.txt";
  ASSERT_TRUE(writeFileAtomic(target, std::string("earlier")).isOk());
  // A target whose directory does not exist cannot be staged: nothing at all is created.
  const Status missingDir = writeFileAtomic(dir / "missing" / "out.txt", std::string("x"));
  EXPECT_EQ(missingDir.code(), ExitCode::Io);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  // Renaming over a non-empty directory fails after the temporary was written: it must be removed.
  fs::create_directories(dir / "busy" / "child");
  const Status busy = writeFileAtomic(dir / "busy", std::string("x"));
  EXPECT_EQ(busy.code(), ExitCode::Io);
  EXPECT_EQ(readText(target), "earlier");
  EXPECT_EQ(entriesIn(dir), 2u) << "only out.txt and busy/ may exist";
}

TEST(AtomicFile, OutputSetCommitsAllOrNothing) {
  const fs::path dir = test::freshTempDir("atomic_set");
  {
    OutputSet outputs;
    ASSERT_TRUE(outputs.stage(dir / "a.txt", std::string("A")).isOk());
    ASSERT_TRUE(outputs.stage(dir / "b.txt", std::string("B")).isOk());
    EXPECT_FALSE(fs::exists(dir / "a.txt"));
    // Dropped without commit: a failed bake.
  }
  EXPECT_EQ(entriesIn(dir), 0u);
  OutputSet outputs;
  ASSERT_TRUE(outputs.stage(dir / "a.txt", std::string("A")).isOk());
  ASSERT_TRUE(outputs.stage(dir / "b.txt", std::string("B")).isOk());
  ASSERT_TRUE(outputs.commit().isOk());
  EXPECT_EQ(readText(dir / "a.txt"), "A");
  EXPECT_EQ(readText(dir / "b.txt"), "B");
  EXPECT_EQ(entriesIn(dir), 2u);
}

TEST(AtomicFile, ReadReportsMissingAndDirectories) {
  const fs::path dir = test::freshTempDir("atomic_read");
  EXPECT_EQ(readFileBytes(dir / "nope").status().code(), ExitCode::Io);
  EXPECT_EQ(readFileBytes(dir).status().code(), ExitCode::Io);
  EXPECT_NE(readFileBytes(dir).status().message().find("directory"), std::string::npos);
}

}  // namespace
}  // namespace bake
