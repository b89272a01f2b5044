#include "core/depfile.h"

#include "bake/core/atomic_file.h"
#include "core/build_syntax.h"

namespace bake {
namespace fs = std::filesystem;

Result<std::string> escapeDepfilePath(const std::string& path) { return makeEscapedPath(path); }

namespace {
Result<std::string> absoluteEscaped(const fs::path& path) {
  std::error_code ec;
  fs::path absolute = fs::absolute(path, ec);
  if (ec) absolute = path;
  return escapeDepfilePath(absolute.lexically_normal().string());
}
}  // namespace

Result<std::string> formatDepfile(const std::vector<fs::path>& outputs, const std::vector<fs::path>& inputs) {
  std::string text;
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    if (i) text += " \\\n ";
    BAKE_ASSIGN_OR_RETURN(const std::string output, absoluteEscaped(outputs[i]));
    text += output;
  }
  text += ":";
  for (const fs::path& input : inputs) {
    BAKE_ASSIGN_OR_RETURN(const std::string escaped, absoluteEscaped(input));
    text += " \\\n  " + escaped;
  }
  text += "\n";
  return text;
}

Status writeDepfile(const fs::path& depfile, const std::vector<fs::path>& outputs,
                    const std::vector<fs::path>& inputs) {
  BAKE_ASSIGN_OR_RETURN(const std::string text, formatDepfile(outputs, inputs));
  return writeFileAtomic(depfile, text);
}

}  // namespace bake
