#include <gtest/gtest.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstring>
#include <filesystem>
#include <set>

#include "bake/core/atomic_file.h"
#include "core/temporaries.h"
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

// Runs `work` in a child process and returns the signal that ended it (0 if it exited).
template <class Work>
int signalEndingChild(Work work) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    work();
    ::_exit(0);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status) ? WTERMSIG(status) : 0;
}

TEST(AtomicFile, KilledMidWriteLeavesEarlierOutputAndNoTemporary) {
  const fs::path dir = test::freshTempDir("atomic_killed");
  const fs::path target = dir / "out.bin";
  ASSERT_TRUE(writeFileAtomic(target, std::string("earlier")).isOk());
  // A 64 KiB file-size limit and a 1 MiB output: the kernel sends SIGXFSZ inside write().
  const int signal = signalEndingChild([&] {
    const rlimit limit{64 * 1024, 64 * 1024};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    (void)writeFileAtomic(target, std::vector<std::uint8_t>(1 << 20, 0xAB));
  });
  EXPECT_EQ(signal, SIGXFSZ);
  EXPECT_EQ(readText(target), "earlier");
  EXPECT_EQ(entriesIn(dir), 1u) << "the temporary file must be removed before the process dies";
}

TEST(AtomicFile, SignalBeforeCommitRemovesStagedTemporaries) {
  const fs::path dir = test::freshTempDir("atomic_terminated");
  ASSERT_TRUE(writeFileAtomic(dir / "a.txt", std::string("earlier")).isOk());
  const int signal = signalEndingChild([&] {
    OutputSet outputs;
    (void)outputs.stage(dir / "a.txt", std::string("A"));
    (void)outputs.stage(dir / "b.txt", std::string("B"));
    ::raise(SIGTERM);
  });
  EXPECT_EQ(signal, SIGTERM);
  EXPECT_EQ(readText(dir / "a.txt"), "earlier");
  EXPECT_EQ(entriesIn(dir), 1u);
}

TEST(AtomicFile, IgnoredSignalStaysIgnored) {
  // A caller that ignores SIGHUP (nohup) keeps it ignored: the staged file survives the signal.
  const fs::path dir = test::freshTempDir("atomic_nohup");
  const int signal = signalEndingChild([&] {
    ::signal(SIGHUP, SIG_IGN);
    OutputSet outputs;
    (void)outputs.stage(dir / "a.txt", std::string("A"));
    ::raise(SIGHUP);
    (void)outputs.commit();
  });
  EXPECT_EQ(signal, 0);
  EXPECT_EQ(readText(dir / "a.txt"), "A");
}

TEST(AtomicFile, RegisteredTemporariesGetFreshNamesWithTheirSuffix) {
  const fs::path dir = test::freshTempDir("atomic_names");
  std::set<std::string> names;
  for (int i = 0; i < 200; ++i) {
    std::string pattern = (dir / ".out.tmp.XXXXXX.png").string();
    const int fd = createRegisteredTemporary(pattern, 4);
    ASSERT_GE(fd, 0) << std::strerror(errno);
    ::close(fd);
    EXPECT_TRUE(fs::is_regular_file(pattern));
    EXPECT_EQ(pattern.substr(pattern.size() - 4), ".png");
    EXPECT_EQ(pattern.find("XXXXXX"), std::string::npos);
    names.insert(pattern);
    unregisterTemporary(pattern);
  }
  EXPECT_EQ(names.size(), 200u);
  std::string bad = (dir / "no-placeholder").string();
  EXPECT_EQ(createRegisteredTemporary(bad), -1);
}

TEST(AtomicFile, ReadReportsMissingAndDirectories) {
  const fs::path dir = test::freshTempDir("atomic_read");
  EXPECT_EQ(readFileBytes(dir / "nope").status().code(), ExitCode::Io);
  EXPECT_EQ(readFileBytes(dir).status().code(), ExitCode::Io);
  EXPECT_NE(readFileBytes(dir).status().message().find("directory"), std::string::npos);
}

}  // namespace
}  // namespace bake
