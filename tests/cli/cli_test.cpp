// Data-driven black-box tests: every tests/cli/cases/<tool>/<case>.json runs a tool as a process and
// checks its exit code, stdout (fragments or a golden file), stderr fragments, the files it leaves,
// JSON outputs against a schema, GLB outputs with the Khronos validator, and byte-identical outputs
// for --threads 1 and --threads 2. Paths in a case may use ${source}, ${golden} and ${tmp} (a fresh
// directory per case), and ${byte:XX} for one raw byte (non-UTF-8 names). Cases with a "category"
// form the bad-input corpus and obey stricter rules (CliCase::checkCorpusRules). See
// tests/cli/README.md for the fields.
#include <gtest/gtest.h>
#include <spawn.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <chrono>
#include <fstream>
#include <cstdio>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

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

int hexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// "676c5446" -> the bytes; whitespace between pairs is allowed. Throws on anything else.
std::vector<std::uint8_t> fromHex(const std::string& text) {
  std::vector<std::uint8_t> bytes;
  for (std::size_t i = 0; i < text.size();) {
    if (std::isspace(static_cast<unsigned char>(text[i]))) {
      ++i;
      continue;
    }
    const int high = hexDigit(text[i]), low = i + 1 < text.size() ? hexDigit(text[i + 1]) : -1;
    if (high < 0 || low < 0) throw std::invalid_argument("not hex at character " + std::to_string(i) + " of \"" + text + "\"");
    bytes.push_back(std::uint8_t(high * 16 + low));
    i += 2;
  }
  return bytes;
}

// ${byte:XX} -> the raw byte 0xXX (for names that are not UTF-8).
std::string expandBytes(std::string text) {
  const std::string open = "${byte:";
  for (std::size_t at = text.find(open); at != std::string::npos; at = text.find(open, at + 1)) {
    const std::size_t close = text.find('}', at);
    const std::vector<std::uint8_t> byte = fromHex(text.substr(at + open.size(), close == std::string::npos ? 0 : close - at - open.size()));
    if (close == std::string::npos || byte.size() != 1) throw std::invalid_argument("bad ${byte:XX} in \"" + text + "\"");
    text.replace(at, close + 1 - at, std::string(1, char(byte[0])));
  }
  return text;
}

// The bad-input corpus: every case with a "category" names one of these.
const std::set<std::string>& corpusCategories() {
  static const std::set<std::string> categories = {
      "truncated",          "wrong-magic",     "huge-count",        "nan-inf",   "negative-size",
      "index-out-of-range", "reference-cycle", "non-utf8",          "empty-file", "directory-as-file",
      "unwritable-output",  "malformed",       "out-of-range",      "usage",     "missing-file"};
  return categories;
}

// What a sanitizer prints when it finds something (the suite also runs in an ASan+UBSan build).
const std::vector<std::string>& sanitizerMarkers() {
  static const std::vector<std::string> markers = {"AddressSanitizer", "LeakSanitizer", "runtime error:"};
  return markers;
}

// Bytes the runner puts where a failing bake would write its output; they must survive it.
const std::string& sentinelBytes() {
  static const std::string bytes = std::string("earlier output, to be kept by a failing bake\n") + '\0' + "\xff\xfe\x01";
  return bytes;
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
  int signal = 0;        // the signal that ended the process, 0 when it exited
  bool timedOut = false;  // killed by the runner after the case's time limit
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
    return expandBytes(text);
  }

  bool inCorpus() const { return spec_.contains("category"); }

  // Files the case prepares before running: text, hex bytes, copies (optionally truncated, with a
  // byte flipped, or patched), directories; then optionally a permission mode.
  void prepareFiles() {
    const json files = spec_.value("files", json::object());
    for (const auto& [rawPath, what] : files.items()) {
      const fs::path path = expand(rawPath);
      fs::create_directories(path.parent_path());
      std::vector<std::uint8_t> bytes;
      if (what.contains("dir")) {
        fs::create_directories(path);
      } else if (what.contains("text")) {
        const std::string text = what["text"].get<std::string>();
        bytes.assign(text.begin(), text.end());
      } else if (what.contains("hex")) {
        bytes = fromHex(what["hex"].get<std::string>());
      } else if (what.contains("copy")) {
        bytes = readAll(expand(what["copy"]));
        ASSERT_FALSE(bytes.empty()) << "nothing to copy from " << what["copy"];
        if (what.contains("truncate")) {
          const std::size_t size = what["truncate"].get<std::size_t>();
          ASSERT_LT(size, bytes.size()) << "truncating " << what["copy"] << " does not shorten it";
          bytes.resize(size);
        }
        if (what.contains("flip")) bytes.at(what["flip"].get<std::size_t>()) ^= 0xFF;
        for (const json& patch : what.value("patch", json::array())) {
          const std::size_t at = patch["at"].get<std::size_t>();
          const std::vector<std::uint8_t> replacement = fromHex(patch["hex"].get<std::string>());
          ASSERT_LE(at + replacement.size(), bytes.size()) << "patch at " << at << " runs past the end of " << what["copy"];
          std::copy(replacement.begin(), replacement.end(), bytes.begin() + std::ptrdiff_t(at));
        }
      } else {
        FAIL() << rawPath << ": a file needs dir, text, hex or copy";
      }
      if (!what.contains("dir")) {
        std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
      }
      if (what.contains("mode")) {
        const std::string mode = what["mode"].get<std::string>();
        ASSERT_EQ(::chmod(path.c_str(), mode_t(std::stoul(mode, nullptr, 8))), 0) << "chmod " << mode << " " << path;
      }
    }
  }

  // The path after -o/--output in the case's args, when "nothing lost" applies to it: inside ${tmp},
  // not made by the case, in a directory that exists. Empty otherwise.
  fs::path sentinelPath() const {
    if (!inCorpus() || !spec_.value("keepsPrevious", true)) return {};
    const json args = spec_.value("args", json::array());
    std::string output;
    for (std::size_t i = 0; i < args.size(); ++i) {
      const std::string arg = args[i].get<std::string>();
      if ((arg == "-o" || arg == "--output") && i + 1 < args.size()) output = args[i + 1].get<std::string>();
      if (arg.rfind("--output=", 0) == 0) output = arg.substr(9);
    }
    if (output.empty()) return {};
    const fs::path path = fs::path(expand(output)).lexically_normal();
    const std::string inside = path.string(), root = tmp_.lexically_normal().string() + "/";
    if (inside.rfind(root, 0) != 0) return {};
    std::error_code error;
    if (fs::exists(fs::symlink_status(path, error)) || !fs::is_directory(path.parent_path(), error)) return {};
    return path;
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
      // A hang is a failure, not a stuck test: the process is killed after the case's time limit.
      const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(spec_.value("timeoutSeconds", 300));
      int status = 0;
      while (waitpid(pid, &status, WNOHANG) == 0) {
        if (std::chrono::steady_clock::now() > deadline) {
          result.timedOut = true;
          kill(pid, SIGKILL);
          waitpid(pid, &status, 0);
          break;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
      }
      if (WIFSIGNALED(status)) result.signal = WTERMSIG(status);
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
    if (spec_.value("stdoutEmpty", false)) EXPECT_EQ(result.out, "");
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
        // Warnings only from the allow-list (tests/js/gltf_allowed_warnings.json, each with its reason).
        EXPECT_EQ(answer.is_object() ? answer.value("numUnallowedWarnings", -1) : -1, 0) << path << ": " << answer.dump(2);
      }
    }
    if (spec_.value("noTemporaries", false) || inCorpus()) {
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

  // The bad-input corpus's rules, for a case with a "category": a failing exit code that is not
  // "internal error" (unless the case says why it expects one), no signal, no hang, a message, no
  // sanitizer report. (No temporaries and "nothing lost" are checked in checkFiles and Behaves.)
  void checkCorpusRules(const ProcessResult& result) const {
    if (!inCorpus()) return;
    const std::string category = spec_["category"].get<std::string>();
    EXPECT_TRUE(corpusCategories().count(category)) << "unknown category \"" << category << "\"";
    EXPECT_FALSE(result.timedOut) << "the tool hung and was killed";
    EXPECT_EQ(result.signal, 0) << "the tool died of signal " << result.signal << ":\n" << result.err;
    const int expected = spec_["exit"].get<int>();
    EXPECT_TRUE(expected >= 1 && expected <= 5) << "a corpus case must expect a failing exit code 1..5, not " << expected;
    if (expected == 4 || result.exitCode == 4) {
      EXPECT_TRUE(spec_.value("internalErrorExpected", false) && !spec_.value("internalErrorReason", std::string()).empty())
          << "exit 4 (internal error) on bad input, and the case gives no internalErrorReason:\n" << result.err;
    }
    EXPECT_FALSE(spec_.value("stderr", json::array()).empty()) << "a corpus case must name at least one stderr fragment";
    for (const std::string& marker : sanitizerMarkers()) {
      EXPECT_EQ(result.err.find(marker), std::string::npos) << "a sanitizer reported a fault:\n" << result.err;
    }
  }

  json spec_;
  fs::path tmp_;
};

TEST_P(CliCase, Behaves) {
  prepareFiles();
  if (HasFatalFailure()) return;
  // "Nothing lost": where a corpus case's output would go, an earlier output that must survive.
  const fs::path sentinel = sentinelPath();
  if (!sentinel.empty()) std::ofstream(sentinel, std::ios::binary) << sentinelBytes();
  const ProcessResult result = run();
  EXPECT_EQ(result.exitCode, spec_["exit"].get<int>()) << "stderr:\n" << result.err << "\nstdout:\n" << result.out;
  checkCorpusRules(result);
  if (!sentinel.empty()) {
    EXPECT_TRUE(fs::is_regular_file(sentinel) && readText(sentinel) == sentinelBytes())
        << "the failing bake did not leave the earlier " << sentinel << " byte-identical";
  }
  checkStreams(result);
  checkFiles();
  checkThreadDeterminism();
  // Further runs in the same ${tmp}, each with its own args and expectations.
  const json steps = spec_.value("then", json::array());
  for (std::size_t i = 0; i < steps.size(); ++i) {
    SCOPED_TRACE("then[" + std::to_string(i) + "]");
    json next = {{"tool", spec_["tool"]}, {"args", spec_["args"]}, {"exit", 0}};
    next.update(steps[i]);
    const bool corpus = inCorpus();
    spec_ = next;
    const ProcessResult again = run();
    EXPECT_EQ(again.exitCode, spec_["exit"].get<int>()) << "stderr:\n" << again.err << "\nstdout:\n" << again.out;
    if (corpus) {
      EXPECT_EQ(again.signal, 0) << "the tool died of signal " << again.signal;
      for (const std::string& marker : sanitizerMarkers()) EXPECT_EQ(again.err.find(marker), std::string::npos) << again.err;
    }
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

// The corpus as a whole: its size, its spread over tools and categories, and known category names
// only. A failing case outside the corpus must say why in "uncategorised".
TEST(BadInputCorpus, CoversEveryCategory) {
  std::map<std::string, int> perCategory;
  std::set<std::string> tools;
  int categorised = 0;
  for (const Case& c : allCases()) {
    std::ifstream in(c.file);
    const json spec = json::parse(in, nullptr, false);
    ASSERT_FALSE(spec.is_discarded()) << c.file;
    if (!spec.contains("category")) {
      if (spec.value("exit", 0) != 0) {
        EXPECT_FALSE(spec.value("uncategorised", std::string()).empty())
            << c.file << ": a failing case needs a category, or a reason in \"uncategorised\"";
      }
      continue;
    }
    ASSERT_TRUE(spec["category"].is_string()) << c.file;
    const std::string category = spec["category"].get<std::string>();
    EXPECT_TRUE(corpusCategories().count(category)) << c.file << ": unknown category \"" << category << "\"";
    ++perCategory[category];
    tools.insert(spec.value("tool", std::string()));
    ++categorised;
  }
  EXPECT_GE(categorised, 75);
  EXPECT_GE(tools.size(), 7u);
  for (const std::string& category : corpusCategories()) {
    EXPECT_GE(perCategory[category], 3) << "category " << category;
  }
}

// ---- Help in our words -------------------------------------------------------------------------

// What `TOOL [SUBCOMMAND] --help` prints (stdout and stderr together).
std::string helpOf(const std::string& tool, const std::string& subcommand) {
  const std::string command = "'" + tool + "'" + (subcommand.empty() ? "" : " " + subcommand) + " --help 2>&1";
  std::string out;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buffer[4096];
    for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
    pclose(pipe);
  }
  return out;
}

// The names listed under "Subcommands:" in a help text.
std::vector<std::string> subcommandsIn(const std::string& help) {
  std::vector<std::string> names;
  std::istringstream lines(help);
  bool inList = false;
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("Subcommands:", 0) == 0) {
      inList = true;
    } else if (inList && line.rfind("  ", 0) == 0 && line.size() > 2 && line[2] != ' ') {
      names.push_back(line.substr(2, line.find(' ', 2) - 2));
    } else if (inList && !line.empty() && line[0] != ' ') {
      inList = false;
    }
  }
  return names;
}

// The lines of `help` that show the parser's own words: CLI11's type names (ENUM:value in {a->0},
// UINT, TEXT, NONNEGATIVE, REQUIRED) or a default as std::to_string writes it (2.500000).
std::vector<std::string> foreignLines(const std::string& help) {
  static const std::regex kForeign(R"(\b(ENUM|UINT|INT|FLOAT|TEXT|NUMBER|NONNEGATIVE|POSITIVE|REQUIRED)\b|->|OR \{|\{(true|false)\}|\d\.\d*00000\b)");
  std::vector<std::string> found;
  std::istringstream lines(help);
  for (std::string line; std::getline(lines, line);)
    if (std::regex_search(line, kForeign)) found.push_back(line);
  return found;
}

TEST(HelpText, EveryToolAndSubcommandSpeaksOurWords) {
  std::size_t helps = 0;
  for (const auto& [name, path] : toolPaths()) {
    const std::string help = helpOf(path, "");
    ASSERT_NE(help.find("Usage:"), std::string::npos) << name << " --help printed:\n" << help;
    std::vector<std::pair<std::string, std::string>> texts{{name, help}};
    for (const std::string& sub : subcommandsIn(help)) texts.push_back({name + " " + sub, helpOf(path, sub)});
    for (const auto& [what, text] : texts) {
      ++helps;
      EXPECT_NE(text.find("Usage:"), std::string::npos) << what << " --help";
      for (const std::string& line : foreignLines(text)) ADD_FAILURE() << what << " --help: " << line;
    }
  }
  EXPECT_GE(helps, toolPaths().size() + 6);  // bakeplay's three subcommands, bakepipe's three
}

TEST(HelpText, TheCheckFindsTheParsersWords) {
  // The check itself, on lines CLI11 printed before the help had its own words.
  EXPECT_EQ(foreignLines("  --method ENUM:value in {exact->0,fmm->2,heat->1} OR {0,2,1}=exact").size(), 1u);
  EXPECT_EQ(foreignLines("  -j,--threads UINT:UINT in [0 - 1024]").size(), 1u);
  EXPECT_EQ(foreignLines("  mesh TEXT REQUIRED          Input mesh").size(), 1u);
  EXPECT_EQ(foreignLines("  --shadow-density FLOAT=2.500000").size(), 1u);
  EXPECT_EQ(foreignLines("  --no-shadows{false}         Bake no shadow table").size(), 1u);
  EXPECT_EQ(foreignLines("  --length X (default: 0.05)  Stroke length, POINTS and TEXTURES").size(), 0u);
}

}  // namespace
}  // namespace bake::test
