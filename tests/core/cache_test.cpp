// The content-addressed cache (--cache-dir): what the key depends on and what it ignores, and that an
// entry is used only when every byte of it is what its manifest says.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "bake/core/cache.h"
#include "bake/core/session.h"
#include "common/cli.h"
#include "support/golden.h"

namespace bake {
namespace {
namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }

// A baker's command line: an input, an output, a tuning option, an enum and the common options.
struct Command {
  std::string input, output, mode = "fast";
  double size = 1;
  std::vector<int> sources;
  CommonOptions common;
};

// The key of one command line, with the run's files as the tool would declare them.
std::string keyOf(const std::vector<std::string>& args) {
  Command command;
  CLI::App app{"test baker", "testbake"};
  app.add_option("input", command.input)->required();
  app.add_option("-o,--output", command.output)->required();
  app.add_option("--size", command.size);
  app.add_option("--mode", command.mode)->check(CLI::IsMember({"fast", "exact"}));
  app.add_option_group("Sources")->add_option("--source", command.sources);
  addCommonOptions(app, command.common, {.cacheDir = true});
  std::vector<std::string> reversed(args.rbegin(), args.rend());  // CLI11 parses a reversed vector
  app.parse(reversed);
  const RunFiles files{{command.input}, {command.output}};
  Result<nlohmann::json> description = describeRun("testbake", "1.0", givenOptions(app), files);
  EXPECT_TRUE(description.isOk()) << description.status().describe();
  return description.isOk() ? cacheKey(*description) : "";
}

class CacheKey : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::freshTempDir("cache_key");
    writeText(dir_ / "in.txt", "input bytes");
    input_ = (dir_ / "in.txt").string();
  }
  fs::path dir_;
  std::string input_;
};

TEST_F(CacheKey, IsStableAndIndependentOfOptionOrder) {
  const std::string key = keyOf({input_, "-o", "out.glb", "--size", "2", "--mode", "exact"});
  EXPECT_EQ(key.size(), 32u);
  EXPECT_EQ(key, keyOf({"--mode", "exact", input_, "--size", "2", "-o", "out.glb"}));
  EXPECT_EQ(key, keyOf({input_, "-o", "out.glb", "--size", "2.0", "--mode", "exact"})) << "the same number";
}

TEST_F(CacheKey, ChangesWithAnOption) {
  const std::string key = keyOf({input_, "-o", "out.glb", "--size", "2"});
  EXPECT_NE(key, keyOf({input_, "-o", "out.glb", "--size", "3"}));
  EXPECT_NE(key, keyOf({input_, "-o", "out.glb", "--size", "2", "--mode", "exact"}));
}

TEST_F(CacheKey, CountsOptionsInOptionGroups) {
  const std::string key = keyOf({input_, "-o", "out.glb", "--source", "1"});
  EXPECT_NE(key, keyOf({input_, "-o", "out.glb", "--source", "2"}));
  EXPECT_NE(key, keyOf({input_, "-o", "out.glb", "--source", "1", "--source", "2"}));
  EXPECT_NE(key, keyOf({input_, "-o", "out.glb"}));
}

TEST_F(CacheKey, ChangesWithOneInputByte) {
  const std::string key = keyOf({input_, "-o", "out.glb"});
  writeText(input_, "input bytes.");
  EXPECT_NE(key, keyOf({input_, "-o", "out.glb"}));
  writeText(input_, "input bytes");
  EXPECT_EQ(key, keyOf({input_, "-o", "out.glb"}));
}

TEST_F(CacheKey, IgnoresThreadsOutputPathAndReportOptions) {
  const std::string key = keyOf({input_, "-o", "out.glb"});
  EXPECT_EQ(key, keyOf({input_, "-o", "out.glb", "-j", "1"}));
  EXPECT_EQ(key, keyOf({input_, "-o", "out.glb", "--threads", "2"}));
  EXPECT_EQ(key, keyOf({input_, "-o", (dir_ / "elsewhere" / "other.glb").string()}));
  EXPECT_EQ(key, keyOf({input_, "-o", "out.glb", "--report", "r.json", "--depfile", "o.d", "-q", "--cache-dir", "c"}));
  // The output's kind is part of the key: another extension may be another format.
  EXPECT_NE(key, keyOf({input_, "-o", "out.obj"}));
}

TEST_F(CacheKey, InputsCountByContentAndName) {
  const std::string key = keyOf({input_, "-o", "out.glb"});
  fs::create_directories(dir_ / "copy");
  fs::copy_file(input_, dir_ / "copy" / "in.txt");
  EXPECT_EQ(key, keyOf({(dir_ / "copy" / "in.txt").string(), "-o", "out.glb"})) << "same content and name elsewhere";
  fs::copy_file(input_, dir_ / "renamed.txt");
  EXPECT_NE(key, keyOf({(dir_ / "renamed.txt").string(), "-o", "out.glb"})) << "tools may name things after their input";
}

TEST_F(CacheKey, UnreadableInputHasNoKey) {
  Command command;
  CLI::App app{"test baker", "testbake"};
  app.add_option("input", command.input);
  app.parse(std::vector<std::string>{(dir_ / "missing.txt").string()});
  EXPECT_FALSE(describeRun("testbake", "1.0", givenOptions(app), {{command.input}, {}}).isOk());
}

CacheEntry sampleEntry() {
  CacheEntry entry;
  entry.outputs = {{1, 2, 3, 4, 5}, {}, {9, 8, 7}};
  entry.report = {{"statistics", {{"vertices", 6}}}};
  return entry;
}

TEST(Cache, StoresAndLoadsAnEntry) {
  const fs::path dir = test::freshTempDir("cache_store");
  const Cache cache(dir / "cache");
  EXPECT_FALSE(cache.load("0123456789abcdef0123456789abcdef").has_value());
  ASSERT_TRUE(cache.store("0123456789abcdef0123456789abcdef", sampleEntry()).isOk());
  const std::optional<CacheEntry> loaded = cache.load("0123456789abcdef0123456789abcdef");
  ASSERT_TRUE(loaded.has_value());
  EXPECT_EQ(loaded->outputs, sampleEntry().outputs);
  EXPECT_EQ(loaded->report, sampleEntry().report);
  // Only the entry remains: no temporary directory.
  std::size_t entries = 0;
  for (const auto& e : fs::directory_iterator(dir / "cache")) {
    EXPECT_EQ(e.path().filename().string().find(".tmp."), std::string::npos) << e.path();
    ++entries;
  }
  EXPECT_EQ(entries, 1u);
  // Storing again keeps the valid entry.
  EXPECT_TRUE(cache.store("0123456789abcdef0123456789abcdef", sampleEntry()).isOk());
  EXPECT_TRUE(cache.load("0123456789abcdef0123456789abcdef").has_value());
}

TEST(Cache, CorruptOrPartialEntryIsAMiss) {
  const std::string key = "00000000000000000000000000000001";
  const fs::path dir = test::freshTempDir("cache_corrupt");
  const Cache cache(dir);
  ASSERT_TRUE(cache.store(key, sampleEntry()).isOk());
  const fs::path entry = cache.entryPath(key);
  const fs::path blob = entry / "0.bin";

  writeText(blob, std::string("\x01\x02\x03\x04\x06", 5));  // one byte changed, same size
  EXPECT_FALSE(cache.load(key).has_value()) << "a changed byte";
  writeText(blob, std::string("\x01\x02\x03\x04", 4));  // truncated
  EXPECT_FALSE(cache.load(key).has_value()) << "a truncated output";
  fs::remove(blob);
  EXPECT_FALSE(cache.load(key).has_value()) << "a missing output";

  // A bad entry is replaced by the next store.
  ASSERT_TRUE(cache.store(key, sampleEntry()).isOk());
  ASSERT_TRUE(cache.load(key).has_value());

  fs::remove(entry / "manifest.json");
  EXPECT_FALSE(cache.load(key).has_value()) << "no manifest: a partial entry";
  ASSERT_TRUE(cache.store(key, sampleEntry()).isOk());
  writeText(entry / "manifest.json", "{\"schema\": \"bake-cache-entry\", \"vers");
  EXPECT_FALSE(cache.load(key).has_value()) << "a truncated manifest";
  ASSERT_TRUE(cache.store(key, sampleEntry()).isOk());
  // An entry filed under another key is not this key's.
  fs::rename(entry, cache.entryPath("00000000000000000000000000000002"));
  EXPECT_FALSE(cache.load("00000000000000000000000000000002").has_value());
}

}  // namespace
}  // namespace bake
