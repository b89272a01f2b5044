// The bounded reader (core/input_file.h): one open, a bound for every kind of file, devices
// refused, pipes read once without blocking, system errors as I/O errors, byte-order marks.
#include <gtest/gtest.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <filesystem>
#include <thread>

#include "bake/core/atomic_file.h"
#include "bake/core/input_file.h"
#include "bake/core/limits.h"
#include "core/hash.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

TEST(InputFile, DeviceNodesAreRefusedWithoutReading) {
  for (const char* device : {"/dev/zero", "/dev/urandom", "/dev/null"}) {
    const Result<std::vector<std::uint8_t>> bytes = readFileBytes(device);
    ASSERT_FALSE(bytes.isOk()) << device;
    EXPECT_EQ(bytes.status().code(), ExitCode::Io);
    EXPECT_NE(bytes.status().message().find("character device"), std::string::npos) << bytes.status().message();
  }
}

TEST(InputFile, AFifoWithoutWriterIsAnIoErrorNotAHang) {
  const fs::path dir = test::freshTempDir("input_fifo_alone");
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  const Result<std::vector<std::uint8_t>> bytes = readFileBytes(dir / "fifo");  // waits kPipeIdleSeconds
  ASSERT_FALSE(bytes.isOk());
  EXPECT_EQ(bytes.status().code(), ExitCode::Io);
  EXPECT_NE(bytes.status().message().find("no writer"), std::string::npos) << bytes.status().message();
}

TEST(InputFile, AFifoIsReadOnceAndItsHashRemembered) {
  const fs::path dir = test::freshTempDir("input_fifo_writer");
  const fs::path fifo = dir / "fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string payload(200000, 'p');  // more than a pipe buffer: the reader must wait for the rest
  // Opened for reading and writing, the FIFO has a writer at once (no wait for a reader, no SIGPIPE).
  const int fd = ::open(fifo.c_str(), O_RDWR);
  ASSERT_GE(fd, 0);
  std::thread writer([&] {
    std::size_t written = 0;
    while (written < payload.size()) {
      const ssize_t n = ::write(fd, payload.data() + written, payload.size() - written);
      if (n <= 0) break;
      written += std::size_t(n);
    }
    ::close(fd);
  });
  const Result<std::vector<std::uint8_t>> bytes = readFileBytes(fifo);
  writer.join();
  ASSERT_TRUE(bytes.isOk()) << bytes.status().describe();
  ASSERT_EQ(bytes->size(), payload.size());
  const std::optional<std::string> remembered = hashOfReadInput(fifo);
  ASSERT_TRUE(remembered.has_value());
  EXPECT_EQ(*remembered, hashBytes(*bytes));
  // The report hashes it from memory: a second open of the FIFO would block.
  const Result<std::string> hashed = hashFile(fifo);
  ASSERT_TRUE(hashed.isOk());
  EXPECT_EQ(*hashed, *remembered);
}

TEST(InputFile, ReadErrorsAreIoErrors) {
  // /proc/self/mem reports size 0 and fails the first read with EIO.
  const Result<std::vector<std::uint8_t>> bytes = readFileBytes("/proc/self/mem");
  ASSERT_FALSE(bytes.isOk());
  EXPECT_EQ(bytes.status().code(), ExitCode::Io);
}

TEST(InputFile, FilesOfUnknownSizeStopAtTheBudget) {
  const Budgets saved = budgets();
  Budgets small = saved;
  small.inputBytes = 100;
  setBudgets(small);
  // /proc files say 0 bytes but hold more: the bound holds whatever the size said.
  const Result<std::vector<std::uint8_t>> bytes = readFileBytes("/proc/self/maps");
  setBudgets(saved);
  ASSERT_FALSE(bytes.isOk());
  EXPECT_EQ(bytes.status().code(), ExitCode::InvalidInput);
  EXPECT_NE(bytes.status().message().find("--budget input-bytes"), std::string::npos) << bytes.status().message();
}

TEST(InputFile, ByteOrderMarkIsDropped) {
  EXPECT_EQ(withoutByteOrderMark("\xEF\xBB\xBFv 0 0 0"), "v 0 0 0");
  EXPECT_EQ(withoutByteOrderMark("v 0 0 0"), "v 0 0 0");
  EXPECT_EQ(withoutByteOrderMark("\xEF\xBB"), "\xEF\xBB");
}

}  // namespace
}  // namespace bake
