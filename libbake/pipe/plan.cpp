// Bake plans (pipe/plan.h). Placeholder for makePlan; tool location and quoting are final.
#include "pipe/plan.h"

namespace bake::pipe {

namespace fs = std::filesystem;

fs::path locateTool(const std::string& tool, const fs::path& directory) {
  if (directory.empty()) return tool;
  std::error_code ec;
  if (fs::is_regular_file(directory / tool, ec)) return directory / tool;
  const fs::path buildTree = (directory / ".." / tool / tool).lexically_normal();
  if (fs::is_regular_file(buildTree, ec)) return buildTree;
  return tool;
}

std::string shellQuote(const std::string& word) {
  bool plain = !word.empty();
  for (const char c : word)
    plain = plain && (std::isalnum(static_cast<unsigned char>(c)) || std::string("_./=:,+-").find(c) != std::string::npos);
  if (plain) return word;
  std::string quoted = "'";
  for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

std::string commandLine(const Step& step, const fs::path& toolDirectory) {
  std::string line = shellQuote(locateTool(step.tool, toolDirectory).string());
  for (const std::string& argument : step.arguments) line += " " + shellQuote(argument);
  return line;
}

nlohmann::json Plan::toJson() const { return nlohmann::json::object(); }
Result<Plan> makePlan(const Scene&, const PlanSettings&) { return unsupported("not yet"); }

}  // namespace bake::pipe
