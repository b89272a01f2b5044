// Data-driven black-box tests: every tests/cli/cases/<tool>/<case>.json runs a tool as a process and
// checks its exit code, stdout (fragments or a golden file), stderr fragments, the files it leaves,
// JSON outputs against a schema, GLB outputs with the Khronos validator, and byte-identical outputs
// for --threads 1 and --threads 2. Paths in a case may use ${source}, ${golden} and ${tmp} (a fresh
// directory per case). See tests/cli/README.md for the fields.
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <unistd.h>

#include <fstream>
#include <map>

#include <nlohmann/json.hpp>

#include "support/golden.h"
#include "support/node_check.h"

extern char** environ;

namespace bake::test {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;

std::map<std::string, std::string> toolPaths() {
  std::map<std::string, std::string> tools;
  std::string list = BAKE_TOOLS;  // "name=path,name=path"
  std::size_t start = 0;
  while (start < list.size()) {
    std::size_t end = list.find(',', start);
    if (end == std::string::npos) end = list.size();
    const std::string entry = list.substr(start, end - start);
    const std::size_t eq = entry.find('=');
    tools[entry.substr(0, eq)] = entry.substr(eq + 1);
    start = end + 1;
  }
  return tools;
}

struct Case {
  std::string name;  // tool/case
  fs::path file;
};

// Names the case in gtest's messages instead of dumping its bytes.
void PrintTo(const Case& c, std::ostream* out) { *out << c.file.string(); }

std::vector<Case> allCases() {
  std::vector<Case> cases;
  const fs::path root = sourceDir() / "tests" / "cli" / "cases";
  for (const auto& tool : fs::directory_iterator(root)) {
    for (const auto& file : fs::directory_iterator(tool.path())) {
      if (file.path().extension() == ".json") {
        cases.push_back({tool.path().filename().string() + "_" + file.path().stem().string(), file.path()});
      }
    }
  }
  std::sort(cases.begin(), cases.end(), [](const Case& a, const Case& b) { return a.name < b.name; });
  return cases;
}

std::string readText(const fs::path& path) {
  const auto bytes = readAll(path);
  return {bytes.begin(), bytes.end()};
}

void replaceAll(std::string& text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
}

// This process's environment with the case's changes: a string sets a variable, null removes it.
std::vector<std::string> environmentFor(const json& changes) {
  std::vector<std::string> out;
  for (char** entry = environ; *entry; ++entry) {
    const std::string text = *entry;
    if (!changes.contains(text.substr(0, text.find('=')))) out.push_back(text);
  }
  for (const auto& [name, value] : changes.items()) {
    if (value.is_string()) out.push_back(name + "=" + value.get<std::string>());
  }
  return out;
}

struct ProcessResult {
  int exitCode = -1;
  std::string out, err;
};

class CliCase : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    std::ifstream in(GetParam().file);
    spec_ = json::parse(in, nullptr, false);
    ASSERT_FALSE(spec_.is_discarded()) << GetParam().file << " is not valid JSON";
    tmp_ = freshTempDir("cli/" + GetParam().name);
  }

  std::string expand(std::string text) const {
    replaceAll(text, "${source}", sourceDir().string());
    replaceAll(text, "${golden}", (sourceDir() / "tests" / "golden").string());
    replaceAll(text, "${tmp}", tmp_.string());
    return text;
  }

  // Files the case prepares before running: text, copies (optionally truncated or with a byte
  // flipped), directories.
  void prepareFiles() {
    const json files = spec_.value("files", json::object());
    for (const auto& [rawPath, what] : files.items()) {
      const fs::path path = expand(rawPath);
      fs::create_directories(path.parent_path());
      if (what.contains("dir")) {
        fs::create_directories(path);
      } else if (what.contains("text")) {
        std::ofstream(path, std::ios::binary) << what["text"].get<std::string>();
      } else if (what.contains("copy")) {
        std::vector<std::uint8_t> bytes = readAll(expand(what["copy"]));
        ASSERT_FALSE(bytes.empty()) << "nothing to copy from " << what["copy"];
        if (what.contains("truncate")) bytes.resize(what["truncate"].get<std::size_t>());
        if (what.contains("flip")) bytes.at(what["flip"].get<std::size_t>()) ^= 0xFF;
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
      }
    }
  }

  ProcessResult run(const std::vector<std::string>& extra = {}) const {
    const auto tools = toolPaths();
    const std::string tool = spec_["tool"];
    EXPECT_TRUE(tools.count(tool)) << "unknown tool " << tool;
    std::vector<std::string> args = {tools.count(tool) ? tools.at(tool) : tool};
    for (const json& arg : spec_.value("args", json::array())) args.push_back(expand(arg.get<std::string>()));
    args.insert(args.end(), extra.begin(), extra.end());
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);

    const fs::path outPath = tmp_ / ".stdout", errPath = tmp_ / ".stderr";
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, outPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, errPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    std::vector<std::string> environment = environmentFor(spec_.value("env", json::object()));
    std::vector<char*> envp;
    for (std::string& entry : environment) envp.push_back(entry.data());
    envp.push_back(nullptr);
    pid_t pid = 0;
    ProcessResult result;
    if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), envp.data()) == 0) {
      int status = 0;
      waitpid(pid, &status, 0);
      result.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    posix_spawn_file_actions_destroy(&actions);
    result.out = readText(outPath);
    result.err = readText(errPath);
    fs::remove(outPath);
    fs::remove(errPath);
    return result;
  }

  void checkStreams(const ProcessResult& result) {
    for (const json& fragment : spec_.value("stdout", json::array())) {
      EXPECT_NE(result.out.find(expand(fragment)), std::string::npos) << "stdout lacks \"" << expand(fragment) << "\":\n" << result.out;
    }
    for (const json& fragment : spec_.value("stderr", json::array())) {
      EXPECT_NE(result.err.find(expand(fragment)), std::string::npos) << "stderr lacks \"" << expand(fragment) << "\":\n" << result.err;
    }
    if (spec_.value("stderrEmpty", false)) EXPECT_EQ(result.err, "");
    if (spec_.contains("stdoutGolden")) {
      std::string normalised = result.out;
      replaceAll(normalised, sourceDir().string(), "${source}");
      replaceAll(normalised, tmp_.string(), "${tmp}");
      EXPECT_TRUE(matchesGolden(spec_["stdoutGolden"], normalised));
    }
  }

  // The JSON chunk of a GLB (glTF 2.0, 4.4.3: it follows the 12-byte header and an 8-byte chunk header).
  static json glbJson(const fs::path& path) {
    const std::vector<std::uint8_t> bytes = readAll(path);
    if (bytes.size() < 20) return json::object();
    const std::uint32_t length = std::uint32_t(bytes[12]) | std::uint32_t(bytes[13]) << 8 |
                                 std::uint32_t(bytes[14]) << 16 | std::uint32_t(bytes[15]) << 24;
    if (bytes.size() < 20 + std::size_t(length)) return json::object();
    return json::parse(bytes.begin() + 20, bytes.begin() + 20 + length, nullptr, false);
  }

  void checkFiles() {
    const json expectations = spec_.value("expectFiles", json::object());
    for (const auto& [rawPath, expected] : expectations.items()) {
      const fs::path path = expand(rawPath);
      if (expected.contains("exists")) EXPECT_EQ(fs::exists(path), expected["exists"].get<bool>()) << path;
      if (expected.contains("text")) EXPECT_EQ(readText(path), expected["text"].get<std::string>()) << path;
      if (expected.contains("sameBytesAs")) {
        const fs::path other = expand(expected["sameBytesAs"].get<std::string>());
        EXPECT_TRUE(fs::exists(path) && readAll(path) == readAll(other)) << path << " differs from " << other;
      }
      if (expected.contains("contains")) {
        for (const json& fragment : expected["contains"]) {
          EXPECT_NE(readText(path).find(expand(fragment)), std::string::npos) << path << " lacks " << expand(fragment);
        }
      }
      if (expected.contains("schema")) {
        const json answer = runNodeChecker("check_schema.mjs", {(sourceDir() / expected["schema"].get<std::string>()).string(), path.string()});
        EXPECT_TRUE(answer.is_object() && answer.value("valid", false)) << path << ": " << answer.dump(2);
      }
      if (expected.contains("extensionSchema")) {
        // {"BAKE_x": "formats/x.schema.json"}: the root extension object of a GLB against its schema.
        for (const auto& [name, schema] : expected["extensionSchema"].items()) {
          const json document = glbJson(path);
          ASSERT_TRUE(document.contains("extensions") && document["extensions"].contains(name)) << path << " lacks " << name;
          const fs::path extracted = tmp_ / (name + ".extension.json");
          std::ofstream(extracted) << document["extensions"][name].dump();
          const json answer = runNodeChecker("check_schema.mjs", {(sourceDir() / schema.get<std::string>()).string(), extracted.string()});
          EXPECT_TRUE(answer.is_object() && answer.value("valid", false)) << path << ": " << name << ": " << answer.dump(2);
        }
      }
      if (expected.contains("materialExtensionSchema")) {
        // {"BAKE_x": "formats/x.schema.json"}: that extension of every material carrying it.
        for (const auto& [name, schema] : expected["materialExtensionSchema"].items()) {
          const json document = glbJson(path);
          int checked = 0;
          for (const json& material : document.value("materials", json::array())) {
            if (!material.contains("extensions") || !material["extensions"].contains(name)) continue;
            const fs::path extracted = tmp_ / (name + ".material" + std::to_string(checked++) + ".json");
            std::ofstream(extracted) << material["extensions"][name].dump();
            const json answer = runNodeChecker("check_schema.mjs", {(sourceDir() / schema.get<std::string>()).string(), extracted.string()});
            EXPECT_TRUE(answer.is_object() && answer.value("valid", false)) << path << ": " << name << ": " << answer.dump(2);
          }
          EXPECT_GT(checked, 0) << path << ": no material carries " << name;
        }
      }
      if (expected.value("gltfValid", false)) {
        const json answer = runNodeChecker("validate_gltf.mjs", {path.string()});
        EXPECT_EQ(answer.is_object() ? answer.value("numErrors", -1) : -1, 0) << path << ": " << answer.dump(2);
      }
    }
    if (spec_.value("noTemporaries", false)) {
      for (const auto& entry : fs::recursive_directory_iterator(tmp_)) {
        EXPECT_EQ(entry.path().filename().string().find(".tmp."), std::string::npos) << "left behind: " << entry.path();
      }
    }
  }

  void checkThreadDeterminism() {
    const json outputs = spec_.value("threadsDeterministic", json::array());
    if (outputs.empty()) return;
    std::map<std::string, std::vector<std::uint8_t>> first;
    for (const char* threads : {"1", "2"}) {
      const ProcessResult result = run({"--threads", threads});
      ASSERT_EQ(result.exitCode, 0) << "--threads " << threads << ":\n" << result.err;
      for (const json& output : outputs) {
        const std::vector<std::uint8_t> bytes = readAll(expand(output));
        ASSERT_FALSE(bytes.empty()) << expand(output);
        if (first.count(output)) {
          EXPECT_EQ(first[output], bytes) << expand(output) << " differs between --threads 1 and --threads 2";
        } else {
          first[output] = bytes;
        }
      }
    }
  }

  json spec_;
  fs::path tmp_;
};

TEST_P(CliCase, Behaves) {
  prepareFiles();
  const ProcessResult result = run();
  EXPECT_EQ(result.exitCode, spec_["exit"].get<int>()) << "stderr:\n" << result.err << "\nstdout:\n" << result.out;
  checkStreams(result);
  checkFiles();
  checkThreadDeterminism();
  // Further runs in the same ${tmp}, each with its own args and expectations.
  const json steps = spec_.value("then", json::array());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    SCOPED_TRACE("then[" + std::to_string(i) + "]");
    json next = {{"tool", spec_["tool"]}, {"args", spec_["args"]}, {"exit", 0}};
    next.update(steps[i]);
    spec_ = next;
    const ProcessResult again = run();
    EXPECT_EQ(again.exitCode, spec_["exit"].get<int>()) << "stderr:\n" << again.err << "\nstdout:\n" << again.out;
    checkStreams(again);
    checkFiles();
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, CliCase, ::testing::ValuesIn(allCases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           std::string name = info.param.name;
                           for (char& c : name) if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
}  // namespace bake::test
