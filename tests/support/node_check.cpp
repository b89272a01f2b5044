#include "support/node_check.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>

#include "support/golden.h"

namespace bake::test {

namespace {
std::string shellQuote(const std::string& text) {
  std::string out = "'";
  for (char c : text) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}
}  // namespace

nlohmann::json runNodeChecker(const std::string& script, const std::vector<std::string>& arguments) {
  const std::filesystem::path js = sourceDir() / "tests" / "js";
  if (!std::filesystem::exists(js / "node_modules")) {
    ADD_FAILURE() << "the Node.js checkers are not installed: run scripts/setup.sh";
    return nullptr;
  }
  std::string command = "node " + shellQuote((js / script).string());
  for (const std::string& argument : arguments) command += " " + shellQuote(argument);
  command += " 2>&1";
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) {
    ADD_FAILURE() << "cannot run " << command;
    return nullptr;
  }
  std::string output;
  std::array<char, 4096> chunk{};
  while (std::size_t n = std::fread(chunk.data(), 1, chunk.size(), pipe)) output.append(chunk.data(), n);
  const int status = ::pclose(pipe);
  nlohmann::json answer = nlohmann::json::parse(output, nullptr, false);
  if (status != 0 || answer.is_discarded()) {
    ADD_FAILURE() << command << " failed (status " << status << "):\n" << output;
    return nullptr;
  }
  return answer;
}

}  // namespace bake::test
